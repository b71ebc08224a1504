#!/usr/bin/env bash
# The real-faces comparison of docs/real-faces.md, in one run: clm3d (rlms and fastncc on the model
# of resources/datasets/real.json) and dlib's 68-point predictor on the LFPW test photos, from each
# one's own detector and from the truth; 20 photo sequences made from LFPW test photos; 5 videos of
# two photos side by side, every face tracked; 5 photos turned -80..80 degrees; franck.mp4; then,
# with the same model, the AFLW bands (scripts/aflw-bands.sh, OUT/aflw), the photo timing
# (scripts/photo-time.sh, OUT/photo-time: it trains real-705.json too) and the model's load time
# (clm3d_bench): every table of that page. AFLW_BANDS=0 and PHOTO_TIME=0 leave those two out.
#
# Usage: scripts/real-faces.sh [OUT]   (default real-faces-out; reruns skip what exists)
# Environment: CLM3D (default build/release/bin/clm3d), CLM3D_DATA (default ../shared/data),
# PEER_DLIB (the peer_dlib binary of ../shared/tools/peer-dlib; built into OUT when absent),
# SCORE (../shared/tools/score_68.py), SEQUENCES (20), FRAMES (120), PAIRS (5),
# TURNED (5), TRAIN_OPTIONS and TRACK_OPTIONS (extra options of clm3d train and of every
# clm3d track, e.g. "--calibrate-views" and "--view-search 0" for the A/B of
# docs/fitting.md#views-on-one-scale; use a fresh OUT for each).
# The model trained here inherits LFPW's and AFLW's research-only terms: it is written to OUT, never
# committed.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-real-faces-out}
CLM3D=${CLM3D:-$PWD/build/release/bin/clm3d}
DATA=${CLM3D_DATA:-$PWD/../shared/data}
TOOLS=$(dirname "$DATA")/tools
SCORE=${SCORE:-$TOOLS/score_68.py}
SEQUENCES=${SEQUENCES:-20}
FRAMES=${FRAMES:-120}
TEST=$DATA/photos/lfpw/test
mkdir -p "$OUT"/{starts,fits,peer,sequences,tracks,logs}
[[ -d $TEST ]] || { echo "real-faces: no LFPW test photos in $TEST" >&2; exit 1; }

# 1. The model: both scans, MakeHuman, ICT, procedural heads, the 805 LFPW training photos and
# AFLW's training faces; `clm3d train` then calibrates its check on the photo pipeline's fits of
# every 7th AFLW training face (1,227; the manifest's calibration_photos).
MODEL=$OUT/real.clm3d
if [[ ! -f $MODEL ]]; then
  /usr/bin/time -f "train: %e s wall, %M KB peak" "$CLM3D" train --dataset resources/datasets/real.json \
    --out "$MODEL" ${TRAIN_OPTIONS:-} 2>&1 | tee "$OUT/logs/train.log" |
    grep -E "^(trained|train: [0-9]+ of|train: [0-9.]+ s|train: the point check|\||curve|train: warning)"
fi

# 2. Starts from the truth: the 5-point start (eye centres, nose tip, mouth corners).
for pts in "$TEST"/*.pts; do
  stem=$(basename "${pts%.pts}")
  [[ -f $OUT/starts/$stem.pts ]] ||
    "$CLM3D" landmarks convert --in "$pts" --out "$OUT/starts/$stem.pts" --to thesis25 \
      --keep 8,11,12,15,16 >/dev/null
done

# 3. clm3d on the LFPW test photos. From the detector as a user runs it: a fit the point check
# rejects is not written, so it counts as a face not found; rlms-detector-kept writes those too
# (--keep-rejected), as the runs before the rejected status did. From the truth's 5 points every
# fit is kept, as the confidence's ROC below needs the rejected ones.
for optimiser in rlms fastncc; do
  for start in detector start5 detector-kept; do
    [[ $start == detector-kept && $optimiser != rlms ]] && continue
    dir=$OUT/fits/$optimiser-$start
    [[ -f $dir/summary.csv ]] && continue
    options=()
    [[ $start == start5 ]] && options=(--init-dir "$OUT/starts" --keep-rejected)
    [[ $start == detector-kept ]] && options=(--keep-rejected)
    "$CLM3D" fit --model "$MODEL" --images "$TEST" --out-dir "$dir" --optimiser "$optimiser" \
      "${options[@]}" --quiet > "$OUT/logs/fit-$optimiser-$start.log" 2>&1
  done
done
# Wrong fits on purpose (starts half an eye distance off) for the confidence's ROC.
for optimiser in rlms fastncc; do
  dir=$OUT/fits/$optimiser-offset
  [[ -f $dir/summary.csv ]] ||
    "$CLM3D" fit --model "$MODEL" --images "$TEST" --out-dir "$dir" --optimiser "$optimiser" \
      --init-dir "$OUT/starts" --start-offset 0.5 --keep-rejected --quiet \
      > "$OUT/logs/fit-$optimiser-offset.log" 2>&1
done

# 4. dlib: its own detector, and a box from the truth.
PEER_DLIB=${PEER_DLIB:-$OUT/peer-build/peer_dlib}
if [[ ! -x $PEER_DLIB ]]; then
  cmake -S "$TOOLS/peer-dlib" -B "$OUT/peer-build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$OUT/peer-build" -j2 >/dev/null
fi
[[ -d $OUT/peer/detector ]] || "$PEER_DLIB" "$TEST"/*.jpg --out "$OUT/peer/detector" > "$OUT/logs/dlib-detector.log"
[[ -d $OUT/peer/truth-box ]] ||
  "$PEER_DLIB" "$TEST"/*.jpg --out "$OUT/peer/truth-box" --box-from-truth "$TEST" > "$OUT/logs/dlib-box.log"

echo "== LFPW test, 224 photos (score_68.py: 19 comparable points, eye-centre normalised)"
for run in fits/rlms-detector fits/rlms-detector-kept fits/rlms-start5 fits/fastncc-detector \
  fits/fastncc-start5; do
  printf '%-22s ' "clm3d ${run#fits/}"
  python3 "$SCORE" --truth "$TEST" --pred "$OUT/$run" --pred-scheme 25 | grep -E "^all "
done
for run in peer/detector peer/truth-box; do
  printf '%-22s ' "dlib ${run#peer/}"
  python3 "$SCORE" --truth "$TEST" --pred "$OUT/$run" | grep -E "^all "
done
echo "== clm3d by landmark (rlms from its detector)"
python3 "$SCORE" --truth "$TEST" --pred "$OUT/fits/rlms-detector" --pred-scheme 25 --per-point | tail -19
echo "== confidence ROC (right: start5, wrong: start offset by 0.5 eye distance)"
for optimiser in rlms fastncc; do
  echo "-- $optimiser"
  "$CLM3D" eval-points --truth-dir "$TEST" --pred-dir "$OUT/fits/$optimiser-start5" \
    --pred-dir "$OUT/fits/$optimiser-offset" --points 1-18,22 --roc | grep -E "ROC|accepting|at confidence"
done

# 5. Photo sequences: the first SEQUENCES test photos moving smoothly, and the last ROLLZOOM test
# photos rolling to 45 degrees and zooming 0.6-1.6x (stems rz_*), tracked with rlms. Each line
# counts the detections (the first frame's and every re-detection) from the track's summary.
ROLLZOOM=${ROLLZOOM:-5}
echo "== $SEQUENCES photo sequences of $FRAMES frames, and $ROLLZOOM rolling to 45 degrees and zooming 0.6-1.6x"
track_sequence() {  # STEM IMAGE SEED [synth options]
  local stem=$1 img=$2 seed=$3 seq=$OUT/sequences/$1
  shift 3
  [[ -f $seq/truth.csv ]] ||
    "$CLM3D" synth --photo "$img" --landmarks "${img%.jpg}.pts" --frames "$FRAMES" --seed "$seed" \
      "$@" --out "$seq" > /dev/null 2>&1
  [[ -f $OUT/tracks/$stem.csv ]] ||
    "$CLM3D" track --model "$MODEL" ${TRACK_OPTIONS:-} --video "$seq"/*.avi --out "$OUT/tracks/$stem.csv" --quiet \
      > "$OUT/logs/track-$stem.log" 2>&1
}
n=0
for img in "$TEST"/*.jpg; do
  (( n++ < SEQUENCES )) || break
  track_sequence "$(basename "${img%.jpg}")" "$img" "$n"
done
n=0
for img in $(ls "$TEST"/*.jpg | tail -n "$ROLLZOOM"); do
  (( ++n ))
  track_sequence "rz_$(basename "${img%.jpg}")" "$img" "$n" --photo-roll 45 --photo-zoom 0.6:1.6
done
for group in image rz_image; do
  compgen -G "$OUT/tracks/${group}_*.csv" > /dev/null || continue  # SEQUENCES=0 or ROLLZOOM=0
  truths=(); preds=(); detections=0
  for tracks in "$OUT"/tracks/${group}_*.csv; do
    stem=$(basename "${tracks%.csv}")
    truths+=("$OUT/sequences/$stem/truth.csv"); preds+=("$tracks")
    found=$(grep -o "[0-9]* detections" "$OUT/logs/track-$stem.log" | grep -o "[0-9]*" || echo "?")
    [[ $found == "?" ]] || detections=$((detections + found))
    "$CLM3D" eval --truth "$OUT/sequences/$stem/truth.csv" --pred "$tracks" --json \
      > "$OUT/tracks/$stem.eval.json" 2>/dev/null || true
    "$CLM3D" eval --truth "$OUT/sequences/$stem/truth.csv" --pred "$tracks" | awk -v stem="$stem" -v found="$found" '
      /^  frames:/ { split($2, n, "/"); tracked = $4; wrong = substr($6, 2) }
      /^  error:/ { mean = $3; sub(",", "", mean) }
      /points within/ { within = $7 }
      END { printf "%-16s %s/%s tracked, %s above 0.3, mean %s, within 0.18 %s, %s detections\n", stem, tracked, n[2], wrong, mean, within, found }'
  done
  echo "${group}_* sequences, pooled ($detections detections, ${#preds[@]} of them first frames):"
  "$CLM3D" eval --truth "${truths[@]}" --pred "${preds[@]}" --label clm3d | grep -E "^  (frames|error|convergence)"
done

# 6. Two faces: PAIRS videos of two LFPW test photos side by side, each moving on its own
# trajectory (synth --beside; the photos after the sequences' ones), tracked with --faces all and
# scored face by face (eval pairs each truth face with the tracked id nearest it).
PAIRS=${PAIRS:-5}
echo "== $PAIRS videos of two photos side by side ($FRAMES frames), track --faces all"
mapfile -t pair_images < <(ls "$TEST"/*.jpg | sed -n "$((SEQUENCES + 1)),$((SEQUENCES + 2 * PAIRS))p")
pair_truths=(); pair_preds=()
for ((p = 0; p + 1 < ${#pair_images[@]}; p += 2)); do
  left=${pair_images[$p]} right=${pair_images[$((p + 1))]}
  stem=pair_$(basename "${left%.jpg}")_$(basename "${right%.jpg}") seq=$OUT/sequences/$stem
  [[ -f $seq/truth.csv ]] ||
    "$CLM3D" synth --photo "$left" --landmarks "${left%.jpg}.pts" --beside "$right" \
      --beside-landmarks "${right%.jpg}.pts" --frames "$FRAMES" --seed $((100 + p)) \
      --out "$seq" > /dev/null 2>&1
  [[ -f $OUT/tracks/$stem.csv ]] ||
    "$CLM3D" track --model "$MODEL" ${TRACK_OPTIONS:-} --video "$seq"/*.avi --faces all --out "$OUT/tracks/$stem.csv" \
      --quiet > "$OUT/logs/track-$stem.log" 2>&1
  pair_truths+=("$seq/truth.csv"); pair_preds+=("$OUT/tracks/$stem.csv")
  echo "$stem: $(grep -o "[0-9]* detections" "$OUT/logs/track-$stem.log" || echo "? detections")"
  "$CLM3D" eval --truth "$seq/truth.csv" --pred "$OUT/tracks/$stem.csv" | grep -E "truth face"
done
if ((${#pair_preds[@]} > 0)); then
  echo "two-face videos, pooled over both faces of every video:"
  "$CLM3D" eval --truth "${pair_truths[@]}" --pred "${pair_preds[@]}" --label clm3d |
    grep -E "^  (frames|error|convergence)"
fi

# 7. Turned photos: TURNED LFPW test photos (the last ones) profiled with the ICT dense face and
# turned -80..80 degrees (synth --photo --yaw-range, 2-degree steps), tracked, scored per |yaw|
# band over the truth's face box (the truth's own pose).
TURNED=${TURNED:-5}
ICT=$DATA/morphable/ict-facekit/ICT-FaceKit_FaceXModel.tar.xz
if [[ -f $ICT && $TURNED -gt 0 ]]; then
  echo "== $TURNED photos turned -80..80 degrees (synth --photo --yaw-range), tracked"
  turned_truths=(); turned_preds=()
  for img in $(ls "$TEST"/*.jpg | tail -n "$TURNED"); do
    stem=turn_$(basename "${img%.jpg}") seq=$OUT/sequences/turn_$(basename "${img%.jpg}")
    [[ -f $seq/truth.csv ]] ||
      "$CLM3D" synth --photo "$img" --landmarks "${img%.jpg}.pts" --yaw-range=-80:80 --step 2 \
        --dense-model "$ICT" --dense-vertices tests/fixtures/ict-facekit/thesis25_vertices.json \
        --out "$seq" > "$OUT/logs/synth-$stem.log" 2>&1
    [[ -f $OUT/tracks/$stem.csv ]] ||
      "$CLM3D" track --model "$MODEL" ${TRACK_OPTIONS:-} --video "$seq"/*.avi --out "$OUT/tracks/$stem.csv" --quiet \
        > "$OUT/logs/track-$stem.log" 2>&1
    turned_truths+=("$seq/truth.csv"); turned_preds+=("$OUT/tracks/$stem.csv")
    echo "$stem: $(grep -o "[0-9]* detections" "$OUT/logs/track-$stem.log" || echo "? detections")"
  done
  "$CLM3D" eval --truth "${turned_truths[@]}" --pred "${turned_preds[@]}" --label clm3d \
    --yaw-bands 0,30,60,90
fi

# 8. franck.mp4: clm3d's track against dlib on every 10th frame (no truth): the frames as images
# (clm3d frames), dlib on them, clm3d's points per frame (clm3d truth --pts), paired by file stem.
FRANCK=$DATA/videos/franck.mp4
if [[ -f $FRANCK ]]; then
  [[ -f $OUT/tracks/franck.csv ]] ||
    "$CLM3D" track --model "$MODEL" ${TRACK_OPTIONS:-} --video "$FRANCK" --out "$OUT/tracks/franck.csv" --quiet \
      > "$OUT/logs/track-franck.log" 2>&1 || true
  mkdir -p "$OUT/franck"
  [[ -d $OUT/franck/frames ]] ||
    "$CLM3D" frames --video "$FRANCK" --out "$OUT/franck/frames" --every 10 --quiet > /dev/null
  [[ -d $OUT/franck/dlib ]] ||
    "$PEER_DLIB" "$OUT"/franck/frames/*.png --out "$OUT/franck/dlib" > "$OUT/logs/dlib-franck.log"
  "$CLM3D" truth --in "$OUT/tracks/franck.csv" --out "$OUT/franck/clm3d.csv" \
    --pts "$OUT/franck/clm3d-pts" > /dev/null
  echo "== franck.mp4: $(head -2 "$OUT/logs/track-franck.log" | tr '\n' ' ')"
  echo "views chosen (frames per view index; clm3d info lists the views):"
  view_column=$(head -1 "$OUT/tracks/franck.csv" | tr ',' '\n' | grep -nx view | cut -d: -f1)
  tail -n +2 "$OUT/tracks/franck.csv" | cut -d, -f"$view_column" | sort -n | uniq -c | tr '\n' ' '
  echo
  printf '%-22s ' "agreement with dlib"
  python3 "$SCORE" --truth "$OUT"/franck/dlib/*.pts --pred "$OUT/franck/clm3d-pts" --pred-scheme 25 |
    grep -E "^all "
fi

# 9. The rest of docs/real-faces.md with the same model: the AFLW bands (and LFPW by band), the
# photo timing (which trains real-705.json for its held-out photos) and the load time.
if [[ ${AFLW_BANDS:-1} == 1 && -f $DATA/photos/aflw21/test.txt ]]; then
  CLM3D=$CLM3D CLM3D_DATA=$DATA PEER_DLIB=$PEER_DLIB LFPW=1 FROM_TRUTH=1 \
    bash scripts/aflw-bands.sh "$MODEL" "$OUT/aflw"
fi
if [[ ${PHOTO_TIME:-1} == 1 ]]; then
  CLM3D=$CLM3D CLM3D_DATA=$DATA SCORE=$SCORE MODEL_ALL=$MODEL \
    bash scripts/photo-time.sh "$OUT/photo-time"
fi
BENCH=$(dirname "$CLM3D")/clm3d_bench
if [[ -x $BENCH ]]; then
  echo "== model load, one core ($BENCH)"
  CLM3D_BENCH_MODEL=$MODEL taskset -c 0 "$BENCH" --benchmark_filter=LoadModel \
    --benchmark_repetitions=3 2>&1 | grep -E "LoadModel.*(median|mean)"
fi
echo "real-faces: results in $OUT"
