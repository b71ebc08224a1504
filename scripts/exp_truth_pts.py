#!/usr/bin/env python3
"""One frame of a tracks CSV (e.g. a synthetic sequence's truth.csv) as a .pts file, for
`clm3d track --init` / `clm3d fit --init` in docs/experiments.md.

Usage: exp_truth_pts.py TRUTH.csv FRAME OUT.pts

Tracks CSVs are 0-based pixels; .pts files are 1-based on disk (docs/landmarks.md), so 1 is added.
"""
import csv
import sys


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    path, frame, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(path, newline="") as f:
        r = csv.DictReader(f)
        n = 0
        while f"x_{n + 1}" in r.fieldnames:
            n += 1
        for row in r:
            if int(row["frame"]) == frame:
                break
        else:
            sys.exit(f"{path}: no frame {frame}")
    with open(out, "w") as f:
        f.write(f"version: 1\nn_points: {n}\n{{\n")
        for k in range(1, n + 1):
            x, y = row[f"x_{k}"], row[f"y_{k}"]
            f.write("nan nan\n" if x == "" else f"{float(x) + 1:.4f} {float(y) + 1:.4f}\n")
        f.write("}\n")


if __name__ == "__main__":
    main()
