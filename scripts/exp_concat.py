#!/usr/bin/env python3
"""Pool several tracks CSVs (docs/tracks-csv.md) into one, for `clm3d eval` over many sequences.

Usage: exp_concat.py OUT.csv IN1.csv [IN2.csv ...]

The frames of the i-th input (0-based) are renumbered frame + 1000 * i, so a pooled truth and a
pooled prediction built from the same list of sequences, in the same order, match frame by frame.
All inputs must have the same header. Standard library only.
"""
import csv
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, inputs = sys.argv[1], sys.argv[2:]
    header = None
    rows = []
    for i, path in enumerate(inputs):
        with open(path, newline="") as f:
            r = csv.reader(f)
            h = next(r)
            if header is None:
                header = h
            elif h != header:
                sys.exit(f"{path}: header differs from {inputs[0]}")
            col = h.index("frame")
            for row in r:
                if not row:
                    continue
                f_ = int(row[col])
                if f_ >= 1000:
                    sys.exit(f"{path}: frame {f_} >= 1000, cannot pool")
                row[col] = str(f_ + 1000 * i)
                rows.append(row)
    with open(out, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


if __name__ == "__main__":
    main()
