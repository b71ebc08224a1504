#!/usr/bin/env python3
"""Per-yaw-bucket and per-region errors (thesis eq. 5.1) from tracks CSVs, for docs/experiments.md.

Usage:
  exp_buckets.py --pred LABEL=TRUTH.csv:PRED.csv [--pred ...] [--buckets 0,15,30,45,60,80]
                 [--min-yaw DEG] [--regions] [--threshold 0.18]

Each --pred pairs a prediction with its ground truth (several sequences of one tracker are
pooled by giving the same LABEL several times). Frames are bucketed by |yaw| of the ground truth.
The error of a frame is the mean point distance divided by the ground truth's distance between
points 8 and 11 (the eye centres), as `clm3d eval` computes it; a frame converges when its row
says success = 1 and its error is below the threshold. Prints Markdown tables. Standard library
only (no numpy).
"""
import argparse
import csv
import math
import statistics
from collections import OrderedDict

# thesis25 regions (1-based point numbers), docs/landmarks.md / DESIGN.md
REGIONS = OrderedDict([
    ("left_eye", [2, 4, 5, 8, 9]),
    ("right_eye", [3, 6, 7, 10, 11]),
    ("nose", [1, 12, 13, 14]),
    ("mouth", [15, 16, 17, 18]),
    ("jaw", [19, 20, 21, 22, 23, 24, 25]),
])


def num(s):
    if s is None or s == "" or s.lower() == "nan":
        return None
    return float(s)


def read_table(path):
    rows = {}
    with open(path, newline="") as f:
        r = csv.DictReader(f)
        n = 0
        while f"x_{n + 1}" in r.fieldnames:
            n += 1
        for row in r:
            pts = []
            for k in range(1, n + 1):
                x, y = num(row[f"x_{k}"]), num(row[f"y_{k}"])
                pts.append(None if x is None or y is None else (x, y))
            rows[int(row["frame"])] = {
                "success": row["success"].strip() in ("1", "true", "True"),
                "yaw": num(row.get("yaw", "")),
                "pts": pts,
            }
    return rows


def frame_errors(truth, pred):
    """Yields (frame, |yaw|, frame error or None, success, point errors dict)."""
    for fr, t in sorted(truth.items()):
        a, b = t["pts"][7], t["pts"][10]
        if a is None or b is None:
            continue
        d = math.dist(a, b)
        if d <= 0:
            continue
        p = pred.get(fr)
        yaw = abs(t["yaw"]) if t["yaw"] is not None else float("nan")
        if p is None:
            yield fr, yaw, None, False, {}
            continue
        pe = {}
        for i, (tp, pp) in enumerate(zip(t["pts"], p["pts"])):
            if tp is not None and pp is not None:
                pe[i + 1] = math.dist(tp, pp) / d
        err = sum(pe.values()) / len(pe) if pe else None
        yield fr, yaw, err, p["success"], pe


def fmt(v, digits=3):
    return "-" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--pred", action="append", required=True, help="LABEL=TRUTH.csv:PRED.csv")
    ap.add_argument("--buckets", default="0,15,30,45,60,80")
    ap.add_argument("--threshold", type=float, default=0.18)
    ap.add_argument("--regions", action="store_true", help="also per-region errors per bucket")
    ap.add_argument("--min-yaw", type=float, default=None,
                    help="with --regions: only frames with |yaw| >= this")
    args = ap.parse_args()
    edges = [float(v) for v in args.buckets.split(",")]
    buckets = list(zip(edges[:-1], edges[1:]))

    data = OrderedDict()  # label -> list of (yaw, err, success, pe)
    for spec in args.pred:
        label, files = spec.split("=", 1)
        tpath, ppath = files.split(":", 1)
        data.setdefault(label, []).extend(
            (yaw, err, ok, pe) for _, yaw, err, ok, pe in frame_errors(read_table(tpath), read_table(ppath)))

    def bucket_of(yaw):
        for i, (lo, hi) in enumerate(buckets):
            if lo <= yaw < hi or (i == len(buckets) - 1 and yaw == hi):
                return i
        return None

    print("| tracker | " + " | ".join(f"{lo:g}-{hi:g}" for lo, hi in buckets) + " | all |")
    print("|---|" + "---|" * (len(buckets) + 1))
    for label, rows in data.items():
        cells = []
        for i in range(len(buckets)):
            errs = [e for y, e, _, _ in rows if bucket_of(y) == i and e is not None]
            cells.append(fmt(statistics.mean(errs)) if errs else "-")
        allerr = [e for _, e, _, _ in rows if e is not None]
        cells.append(fmt(statistics.mean(allerr)) if allerr else "-")
        print(f"| {label} mean error | " + " | ".join(cells) + " |")
        cells = []
        for i in range(len(buckets)):
            sel = [(e, ok) for y, e, ok, _ in rows if bucket_of(y) == i]
            conv = sum(1 for e, ok in sel if ok and e is not None and e < args.threshold)
            cells.append(f"{100.0 * conv / len(sel):.0f}% ({len(sel)})" if sel else "-")
        conv = sum(1 for _, e, ok, _ in rows if ok and e is not None and e < args.threshold)
        cells.append(f"{100.0 * conv / len(rows):.0f}% ({len(rows)})" if rows else "-")
        print(f"| {label} converged (frames) | " + " | ".join(cells) + " |")

    if args.regions:
        print()
        title = "all frames" if args.min_yaw is None else f"frames with |yaw| >= {args.min_yaw:g}"
        print(f"Mean point error per region, {title}:")
        print()
        print("| tracker | frames | " + " | ".join(REGIONS) + " | all points |")
        print("|---|---|" + "---|" * (len(REGIONS) + 1))
        for label, rows in data.items():
            sel = [pe for y, e, _, pe in rows if pe and (args.min_yaw is None or y >= args.min_yaw)]
            cells = []
            for pts in REGIONS.values():
                v = [pe[k] for pe in sel for k in pts if k in pe]
                cells.append(fmt(statistics.mean(v)) if v else "-")
            v = [x for pe in sel for x in pe.values()]
            cells.append(fmt(statistics.mean(v)) if v else "-")
            print(f"| {label} | {len(sel)} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
