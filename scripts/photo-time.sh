#!/usr/bin/env bash
# The photo timing of docs/real-faces.md#time-a-photo: where a photo's landmarking time goes
# (clm3d fit's summary, detection apart) and what spending the start grid and the averaged refiner
# runs only on fits the point check doubts costs in accuracy. On the 100 LFPW training photos held
# out of a model trained on the other 705 (resources/datasets/real-705.json, where the default was
# chosen) and on the 224 LFPW test photos with the model of resources/datasets/real.json. Each run
# pair is fitted in turn on the same idle machine (the held-out pair three times); score_68.py
# scores the 19 comparable points.
#
# Usage: scripts/photo-time.sh [OUT]   (default photo-time-out; reruns skip what exists)
# Environment: CLM3D (default build/release/bin/clm3d), CLM3D_DATA (default ../shared/data),
# SCORE (../shared/tools/score_68.py), MODEL_705 and MODEL_ALL (trained into OUT when absent).
# The models trained here inherit LFPW's research-only terms: they are written to OUT, never
# committed.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-photo-time-out}
CLM3D=${CLM3D:-$PWD/build/release/bin/clm3d}
DATA=${CLM3D_DATA:-$PWD/../shared/data}
SCORE=${SCORE:-$(dirname "$DATA")/tools/score_68.py}
TEST=$DATA/photos/lfpw/test
HELD_OUT=resources/datasets/lfpw-train-heldout.txt
[[ -d $TEST ]] || { echo "photo-time: no LFPW test photos in $TEST" >&2; exit 1; }
mkdir -p "$OUT"/{fits,logs}

train() {  # train DATASET MODEL
  [[ -f $2 ]] || "$CLM3D" train --dataset "$1" --out "$2" > "$OUT/logs/$(basename "$2").log" 2>&1
}
MODEL_705=${MODEL_705:-$OUT/real-705.clm3d}
MODEL_ALL=${MODEL_ALL:-$OUT/real.clm3d}
train resources/datasets/real-705.json "$MODEL_705"
train resources/datasets/real.json "$MODEL_ALL"

# The held-out photos' truth files (the list names the photos).
mapfile -t held_truth < <(grep -v '^#' "$HELD_OUT" | sed "s|^\.\./\.\./\.\./shared/data|$DATA|; s|\.jpg$|.pts|")

# run NAME MODEL IMAGES [options]: fits once, prints the summary's timing and the score.
run() {
  local name=$1 model=$2 images=$3
  shift 3
  local dir=$OUT/fits/$name
  if [[ ! -f $dir/summary.csv ]]; then
    "$CLM3D" fit --model "$model" --images "$images" --out-dir "$dir" --quiet "$@" \
      > "$OUT/logs/$name.log" 2>&1 || true
  fi
  local truth=("$TEST")
  [[ $images == "$HELD_OUT" ]] && truth=("${held_truth[@]}")
  local timing score
  timing=$(grep -o 'fit median [0-9.]* ms (mean [0-9.]*)' "$OUT/logs/$name.log" || echo "no summary")
  score=$(python3 "$SCORE" --truth "${truth[@]}" --pred "$dir" --pred-scheme 25 |
    awk '$1 == "all" { print "mean", $6, "median", $7, "within", $8, "within_all", $9 }')
  printf '%-28s %s | %s\n' "$name" "$timing" "$score"
}

BEFORE=(--start-grid-below 0 --refine-runs-below 0)
echo "== 100 held-out LFPW training photos, model of real-705.json"
# The pair three times in turn: the shared machine's timing moves by about 5 ms from run to run.
for i in 1 2 3; do
  run "heldout-before-$i" "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}"
  run "heldout-default-$i" "$MODEL_705" "$HELD_OUT"
done
run heldout-grid-doubted "$MODEL_705" "$HELD_OUT" --refine-runs-below 0
echo "-- the start grid below other thresholds (the 9 refiner runs always)"
for threshold in 0.9 0.97 0.99 0.999 0.99999; do
  run "heldout-grid-below-$threshold" "$MODEL_705" "$HELD_OUT" --refine-runs-below 0 \
    --start-grid-below "$threshold"
done
echo "-- the before run with one step left out"
run heldout-no-grid "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}" --start-grid 0
run heldout-one-refiner-run "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}" --refine-runs 1
run heldout-no-wider "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}" --wider-search-below 0
run heldout-one-face "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}" --faces-tried 1
run heldout-no-tilts "$MODEL_705" "$HELD_OUT" "${BEFORE[@]}" --tilt-steps 0
echo "== 224 LFPW test photos, model of real.json"
run test-before "$MODEL_ALL" "$TEST" "${BEFORE[@]}"
run test-default "$MODEL_ALL" "$TEST"
