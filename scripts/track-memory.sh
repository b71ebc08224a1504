#!/usr/bin/env bash
# Measures what docs/batch.md reports about long runs: the resident memory of one process tracking
# a long synthetic sequence (a procedural head swept -30 -> +30 degrees and back), sampled from
# /proc/PID/status while it runs. Prints the sample after the first 1,000 frames and the last one,
# and their ratio.
#
#   scripts/track-memory.sh MODEL [FRAMES] [VIDEOS] [CLM3D]
#
# VIDEOS 1: one `clm3d track` over one FRAMES-frame video (the sweep rendered in FRAMES frames),
# sampled against the frames its progress line reports. VIDEOS > 1: one `clm3d batch --threads 1`
# over VIDEOS chained copies of a FRAMES-frame video (the same file listed under other names),
# sampled against the videos finished. FRAMES defaults to 500, VIDEOS to 20 (10,000 frames), CLM3D
# to build/release/bin/clm3d. VIDEO=F tracks that video instead of rendering one (FRAMES must then
# be its frame count).
set -euo pipefail

[ $# -ge 1 ] || {
  echo "usage: $0 MODEL [FRAMES] [VIDEOS] [CLM3D]" >&2
  exit 2
}
model=$1
frames=${2:-500}
videos=${3:-20}
clm3d=${4:-build/release/bin/clm3d}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# frontal -> -30 -> +30 -> frontal is 120 degrees.
video=${VIDEO:-}
if [ -z "$video" ]; then
  step=$(python3 -c "print(f'{120.0 / ($frames - 1):.6f}')")
  "$clm3d" synth --head-seed 7 --texture-size 512 --out "$work/seq" --yaw-range=-30:30 --sweep \
    --step "$step" --size 320x240 --face-size 60 >/dev/null
  video=$work/seq/sequence.avi
fi
: >"$work/samples.txt"
if [ "$videos" -eq 1 ]; then
  # One video: `clm3d track` reports "tracking: P% (N frames)" about once a second.
  "$clm3d" track --model "$model" --video "$video" --out "$work/track.csv" \
    2>"$work/progress.txt" >"$work/summary.txt" &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    rss=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
    tracked=$(tr '\r' '\n' <"$work/progress.txt" | sed -n 's/.*(\([0-9]*\) frames).*/\1/p' | tail -1)
    [ -n "$rss" ] && [ -n "$tracked" ] && echo "$tracked $rss" >>"$work/samples.txt"
    sleep 0.2
  done
  wait "$pid" || true
  cat "$work/summary.txt" >&2
  echo "frames tracked: $(($(wc -l <"$work/track.csv") - 1)) in one video" >&2
else
  mkdir "$work/job"
  for i in $(seq -w 1 "$videos"); do ln -s "$(realpath "$video")" "$work/job/part$i.avi"; done
  "$clm3d" batch --threads 1 --model "$model" --input "$work/job" --out-dir "$work/out" \
    2>"$work/progress.txt" >"$work/summary.txt" &
  pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    rss=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
    # Progress lines are "batch K/N NAME ok ...": K videos finished.
    finished=$(sed -n 's/^batch \([0-9]*\)\/.*/\1/p' "$work/progress.txt" | tail -1)
    [ -n "$rss" ] && [ -n "$finished" ] && echo "$((finished * frames)) $rss" >>"$work/samples.txt"
    sleep 0.2
  done
  wait "$pid" || true
  cat "$work/summary.txt" >&2
  tracked=$(awk -F, 'NR > 1 {sum += $3} END {print sum}' "$work/out/summary.csv")
  echo "frames tracked: $tracked in $videos videos" >&2
fi

python3 - "$work/samples.txt" <<'EOF'
import sys
samples = [tuple(map(int, line.split())) for line in open(sys.argv[1]) if line.strip()]
after = [s for s in samples if s[0] >= 1000]
if not after:
    sys.exit("no sample after frame 1000")
first, last = after[0], after[-1]
peak = max(s[1] for s in after)
# The first sample at or after each multiple of 1,000 frames (and the last).
marks = {}
for frames, rss in samples:
    marks.setdefault(frames // 1000 * 1000, (frames, rss))
marks[samples[-1][0]] = samples[-1]
print("frames: MiB " + ", ".join(f"{f}: {r / 1024:.1f}" for f, r in sorted(marks.values())))
print(f"after {first[0]} frames: {first[1] / 1024:.1f} MiB resident")
print(f"after {last[0]} frames: {last[1] / 1024:.1f} MiB resident ({100.0 * (last[1] / first[1] - 1):+.1f}%)")
print(f"peak from frame {first[0]} on: {peak / 1024:.1f} MiB ({100.0 * (peak / first[1] - 1):+.1f}%)")
EOF
