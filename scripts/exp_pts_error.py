#!/usr/bin/env python3
"""Thesis eq. 5.1 error between two thesis25 .pts files (ground truth first), for docs/experiments.md.

Usage: exp_pts_error.py TRUTH25.pts FIT25.pts [FIT25.pts ...]

Prints one line per fit: mean point distance / truth distance between points 8 and 11 (the eye
centres), over the points present in both (a 68-point mark-up converted to thesis25 has no
earlobes, points 19 and 25), and the share of points within 0.18. Both files use the same .pts
convention (1-based on disk), so the offset cancels.
"""
import math
import sys


def read_pts(path):
    pts = []
    inside = False
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line == "{":
                inside = True
                continue
            if line == "}":
                break
            if inside and line:
                x, y = line.split()[:2]
                pts.append(None if "nan" in (x.lower(), y.lower()) else (float(x), float(y)))
    return pts


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    truth = read_pts(sys.argv[1])
    d = math.dist(truth[7], truth[10])
    for path in sys.argv[2:]:
        fit = read_pts(path)
        errs = [math.dist(t, p) / d for t, p in zip(truth, fit) if t is not None and p is not None]
        within = sum(1 for e in errs if e <= 0.18)
        print(f"{path}: error {sum(errs) / len(errs):.3f} over {len(errs)} points, "
              f"{within}/{len(errs)} within 0.18, eye distance {d:.1f} px")


if __name__ == "__main__":
    main()
