#!/usr/bin/env bash
# The whole-process speed of `clm3d track` on a 300-frame 640x480 H.264 video of a real face, and
# where its time goes (docs/tracking.md, "Progress, cancel, speed"):
#
#   scripts/track-speed.sh OUT MODEL [OTHER_CLM3D]
#
# 1. OUT/seq: `clm3d synth --photo` of LFPW test image_0001 (seed 1, 300 frames, 640x480), needs
#    ../shared/data or $CLM3D_DATA; OUT/seq.mp4: it encoded with libx264 (ffmpeg when installed,
#    else a 20-line OpenCV program built here, OpenCV's FFmpeg writer with the avc1 codec).
# 2. Whole process, RUNS times (default 5) after a warm-up, with /usr/bin/time: wall and CPU
#    seconds and frames a second per run, then the median. With OTHER_CLM3D (another build, e.g.
#    the one before a change), the two run in turn, A B A B ..., and each pair's wall-time ratio
#    other / this is printed with their median: pairs, because this machine's speed drifts.
# 3. The breakdown: scripts/measure.sh track-speed on the same video and model.
#
# CLM3D (default build/release/bin/clm3d) is the build measured.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:?usage: $0 OUT MODEL [OTHER_CLM3D]}
MODEL=${2:?usage: $0 OUT MODEL [OTHER_CLM3D]}
OTHER=${3:-}
CLM3D=${CLM3D:-build/release/bin/clm3d}
RUNS=${RUNS:-5}
DATA=${CLM3D_DATA:-../shared/data}
PHOTO=$DATA/photos/lfpw/test/image_0001
mkdir -p "$OUT"

if [[ ! -f $OUT/seq/truth.csv ]]; then
  "$CLM3D" synth --photo "$PHOTO.jpg" --landmarks "$PHOTO.pts" --frames 300 --size 640x480 \
    --seed 1 --out "$OUT/seq" > /dev/null
fi
if [[ ! -f $OUT/seq.mp4 ]]; then
  if command -v ffmpeg > /dev/null; then
    ffmpeg -loglevel error -y -i "$OUT/seq/sequence.avi" -c:v libx264 -pix_fmt yuv420p "$OUT/seq.mp4"
  else
    cat > "$OUT/h264.cpp" << 'EOF'
#include <opencv2/videoio.hpp>
int main(int argc, char** argv) {
  if (argc != 3) return 2;
  cv::VideoCapture in(argv[1], cv::CAP_FFMPEG);
  const cv::Size size(static_cast<int>(in.get(cv::CAP_PROP_FRAME_WIDTH)),
                      static_cast<int>(in.get(cv::CAP_PROP_FRAME_HEIGHT)));
  cv::VideoWriter out(argv[2], cv::CAP_FFMPEG, cv::VideoWriter::fourcc('a', 'v', 'c', '1'),
                      in.get(cv::CAP_PROP_FPS), size);
  if (!in.isOpened() || !out.isOpened()) return 1;
  for (cv::Mat frame; in.read(frame);) out.write(frame);
}
EOF
    g++ -O2 -std=c++17 "$OUT/h264.cpp" -o "$OUT/h264" $(pkg-config --cflags --libs opencv4)
    "$OUT/h264" "$OUT/seq/sequence.avi" "$OUT/seq.mp4"
  fi
fi

# One whole run: "wall user system" seconds.
run() {
  /usr/bin/time -f "%e %U %S" -o "$OUT/time.txt" "$1" track --model "$MODEL" --video "$OUT/seq.mp4" \
    --out "$OUT/tracks.csv" --quiet > "$OUT/track.log"
  cat "$OUT/time.txt"
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "== whole process: $CLM3D track, $RUNS runs after a warm-up${OTHER:+, in turn with $OTHER}"
run "$CLM3D" > /dev/null
[[ -z $OTHER ]] || run "$OTHER" > /dev/null
walls=() ratios=()
for ((i = 1; i <= RUNS; i++)); do
  read -r wall user system < <(run "$CLM3D")
  line=$(awk -v w="$wall" -v u="$user" -v s="$system" \
    'BEGIN { printf "run %d: %.2f s wall, %.2f s CPU, %.0f frames/s", '"$i"', w, u + s, 300 / w }')
  walls+=("$wall")
  if [[ -n $OTHER ]]; then
    read -r otherWall _ _ < <(run "$OTHER")
    ratio=$(awk -v a="$otherWall" -v b="$wall" 'BEGIN { printf "%.3f", a / b }')
    ratios+=("$ratio")
    line+=", other $otherWall s: ratio other/this $ratio"
  fi
  echo "$line"
done
wall=$(printf '%s\n' "${walls[@]}" | median)
awk -v w="$wall" 'BEGIN { printf "median: %.2f s wall, %.0f frames/s\n", w, 300 / w }'
[[ -z $OTHER ]] || echo "median ratio other/this: $(printf '%s\n' "${ratios[@]}" | median)"
grep -E "tracked|fit time" "$OUT/track.log"

echo "== breakdown (scripts/measure.sh track-speed)"
CLM3D_MEASURE_MODEL=$MODEL CLM3D_MEASURE_VIDEO=$OUT/seq.mp4 scripts/measure.sh track-speed |
  grep -E "^\||frames"
