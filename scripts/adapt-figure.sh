#!/usr/bin/env bash
# The figure of docs/adapt.md, in one run: a `clm3d synth --photo` sequence of an annotated photo
# (640x480, exact truth), tracked with MODEL; every EVERY-th frame "corrected" with its truth (the
# keyframes of a ground truth built by `clm3d truth`); MODEL adapted to those frames (`clm3d
# adapt`, timed); the sequence tracked again with the adapted model; and `clm3d eval` of both
# tracks on the frames that were not corrected.
#
# Usage: scripts/adapt-figure.sh MODEL [OUT]   (default OUT adapt-figure-out; reruns redo all)
# Environment: CLM3D (default build/release/bin/clm3d), CLM3D_DATA (default ../shared/data),
# PHOTO and POINTS (default LFPW test image_0001), FRAMES (200), EVERY (10), SEED (1),
# ADAPT_OPTIONS (extra options for clm3d adapt, e.g. "--prior 50").
# The LFPW photos are research-only: OUT holds renders of them, never commit it.
set -euo pipefail
cd "$(dirname "$0")/.."
MODEL=${1:?usage: scripts/adapt-figure.sh MODEL [OUT]}
OUT=${2:-adapt-figure-out}
CLM3D=${CLM3D:-$PWD/build/release/bin/clm3d}
DATA=${CLM3D_DATA:-$PWD/../shared/data}
PHOTO=${PHOTO:-$DATA/photos/lfpw/test/image_0001.jpg}
POINTS=${POINTS:-${PHOTO%.*}.pts}
FRAMES=${FRAMES:-200}
EVERY=${EVERY:-10}
SEED=${SEED:-1}
read -r -a ADAPT_EXTRA <<< "${ADAPT_OPTIONS:-}"
[[ -f $MODEL ]] || { echo "adapt-figure: no model $MODEL" >&2; exit 1; }
[[ -f $PHOTO && -f $POINTS ]] || { echo "adapt-figure: no photo $PHOTO with $POINTS" >&2; exit 1; }
mkdir -p "$OUT"

"$CLM3D" synth --photo "$PHOTO" --landmarks "$POINTS" --frames "$FRAMES" --seed "$SEED" \
  --size 640x480 --out "$OUT/seq" > "$OUT/synth.log" 2>&1
VIDEO=$OUT/seq/sequence.avi

"$CLM3D" track --model "$MODEL" --video "$VIDEO" --out "$OUT/tracks-general.csv" --quiet \
  > "$OUT/track-general.log" 2>&1

# The truth of every frame as .pts files, and the ground truth: the general track with every
# EVERY-th frame corrected to its truth.
"$CLM3D" truth --in "$OUT/seq/truth.csv" --pts "$OUT/truth-pts" --out "$OUT/truth-copy.csv" \
  > /dev/null
keyframes=()
for ((frame = 0; frame < FRAMES; frame += EVERY)); do
  keyframes+=(--keyframe "$frame=$OUT/truth-pts/$(printf 'frame_%06d.pts' "$frame")")
done
"$CLM3D" truth --in "$OUT/tracks-general.csv" --frames "$FRAMES" "${keyframes[@]}" \
  --out "$OUT/gt.csv" > "$OUT/truth.log"

/usr/bin/time -f "adapt wall time: %e s, peak memory %M kB" "$CLM3D" adapt --model "$MODEL" \
  --video "$VIDEO" --truth "$OUT/gt.csv" --out "$OUT/adapted.clm3d" "${ADAPT_EXTRA[@]}" \
  > "$OUT/adapt.log" 2>&1
"$CLM3D" info "$OUT/adapted.clm3d" | grep -E '^(adapted|notes)' >> "$OUT/adapt.log"

"$CLM3D" track --model "$OUT/adapted.clm3d" --video "$VIDEO" --out "$OUT/tracks-adapted.csv" \
  --quiet > "$OUT/track-adapted.log" 2>&1

# The frames that were not corrected (eval ignores prediction frames the truth lacks).
awk -F, -v every="$EVERY" 'NR == 1 || $1 % every != 0' "$OUT/seq/truth.csv" \
  > "$OUT/truth-not-corrected.csv"
"$CLM3D" eval --truth "$OUT/truth-not-corrected.csv" --pred "$OUT/tracks-general.csv" \
  --pred "$OUT/tracks-adapted.csv" --label general --label adapted > "$OUT/eval.txt"
cat "$OUT/adapt.log" "$OUT/eval.txt"
