#!/usr/bin/env python3
"""Collects the training-data study's evaluations into tables (scripts/training-data-study.sh).

Usage: training_data_results.py EVAL_DIR PHOTO_DIR RESULTS.csv PHOTOS.csv < MODELS

MODELS: one line per model, "NAME HELD_OUT IDENTITIES AUGMENTATION [TRAIN_SECONDS]". Reads
EVAL_DIR/NAME--HELD-{left,right,both}[--truestart].json (clm3d eval --json; "both" pools the two
turns) and
EVAL_DIR/NAME--PHOTO--START.json (clm3d eval-points --json; PHOTO from PHOTO_DIR/*-truth25.pts; a
missing file = the fit failed). RESULTS.csv: one row per model x test (each turn and both turns
pooled, from the detector and from the true first frame; photos from each start); PHOTOS.csv: one
row per model x photo x start; RESULTS.md: one line per model (mean (median), converged share).
Reporting only: every error, pooling and convergence figure comes from clm3d eval / eval-points;
this gathers them into tables (and the photos' mean, median and share below 0.18 over the four
photos' errors). Standard library only.
"""
import glob
import json
import os
import statistics
import sys


def fmt(value):
    return "" if value is None else f"{value:.4f}"


def write(path, rows):
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(rows) + "\n")
    os.replace(path + ".tmp", path)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    evals, photo_dir, results_csv, photos_csv = sys.argv[1:]
    photos = sorted(os.path.basename(t)[: -len("-truth25.pts")]
                    for t in glob.glob(f"{photo_dir}/*-truth25.pts"))
    results = ["model,held_out,identities,augmentation,train_seconds,kind,test,error_mean,"
               "error_median,convergence,scored"]
    per_photo = ["model,held_out,identities,augmentation,photo,start,error,max_error,found,scored"]
    for line in sys.stdin:
        if not line.strip():
            continue
        name, held, n, aug, *seconds = line.split()
        head = f"{name},{held},{n},{aug},{seconds[0] if seconds else ''}"
        for variant in ("", "-truestart"):
            # Each turn, and both turns pooled frame by frame (clm3d eval with both pairs).
            for side in ("left", "right", "both"):
                path = f"{evals}/{name}--{held}-{side}{variant.replace('-', '--')}.json"
                if not os.path.exists(path):
                    continue
                p = json.load(open(path))["predictions"][0]
                kind = f"both{variant}" if side == "both" else f"sequence{variant}"
                results.append(f"{head},{kind},{held}-{side}{variant},"
                               f"{fmt(p['error']['mean'])},{fmt(p['error']['median'])},"
                               f"{fmt(p['convergence_rate'])},{p['frames']['scored']}")
        for start in ("detector", "start5"):
            errors = []
            for photo in photos:
                path = f"{evals}/{name}--{photo}--{start}.json"
                if not os.path.exists(path):
                    per_photo.append(f"{name},{held},{n},{aug},{photo},{start},,,,")
                    continue
                r = json.load(open(path))["predictions"][0]
                errors.append(r["error"])
                per_photo.append(f"{name},{held},{n},{aug},{photo},{start},{fmt(r['error'])},"
                                 f"{fmt(r['max_error'])},{r['found_points']},{r['scored_points']}")
            if photos and start == "detector":
                # The photos where the detector picked the annotated face (a fit of another
                # person is off by more than one eye distance).
                right = [e for e in errors if e is not None and e < 1.0]
                results.append(f"{head},photos,photos-detector-right-face,"
                               f"{fmt(statistics.mean(right)) if right else ''},"
                               f"{fmt(statistics.median(right)) if right else ''},"
                               f"{fmt(sum(e < 0.18 for e in right) / len(right)) if right else ''},"
                               f"{len(right)}")
            if photos:
                ok = [e for e in errors if e is not None]
                # convergence: photos fitted with error < 0.18 over all photos (a failed fit counts
                # as not converged); mean and median over the fitted photos.
                results.append(f"{head},photos,photos-{start},"
                               f"{fmt(statistics.mean(ok)) if ok else ''},"
                               f"{fmt(statistics.median(ok)) if ok else ''},"
                               f"{fmt(sum(e < 0.18 for e in ok) / len(photos))},{len(ok)}")
    write(results_csv, results)
    write(photos_csv, per_photo)
    write(os.path.splitext(results_csv)[0] + ".md", summary_markdown(results))


def summary_markdown(results):
    """One line per model: the pooled turns from each start, the photos; errors as mean (median)."""
    header = results[0].split(",")
    rows = [dict(zip(header, r.split(","))) for r in results[1:]]
    models = []
    for r in rows:
        if r["model"] not in [m["model"] for m in models]:
            models.append(r)
    def cell(model, test, what=("error_mean", "error_median", "convergence")):
        for r in rows:
            if r["model"] == model and r["test"] == test and r["error_mean"]:
                mean, median, conv = (r[w] for w in what)
                return f"{float(mean):.3f} ({float(median):.3f}), {100 * float(conv):.0f}%"
        return "-"
    lines = ["| model | held out | identities | augmentation | train (s) | turns, detector start | "
             "turns, true first frame | photos, 5-point start | photos, detector (right face) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for m in models:
        held = m["held_out"]
        lines.append(f"| {m['model']} | {held} | {m['identities']} | {m['augmentation']} | "
                     f"{m['train_seconds']} | {cell(m['model'], f'{held}-both')} | "
                     f"{cell(m['model'], f'{held}-both-truestart')} | "
                     f"{cell(m['model'], 'photos-start5')} | "
                     f"{cell(m['model'], 'photos-detector-right-face')} |")
    return lines


if __name__ == "__main__":
    main()
