#!/usr/bin/env bash
# Measures what docs/batch.md reports about throughput: COUNT photos fitted by one `clm3d batch`
# process on 1 and on 2 threads, against COUNT separate `clm3d fit` processes (each loading the
# model), and prints a Markdown table with wall times and items per minute.
#
#   scripts/batch-throughput.sh MODEL PHOTO_FOLDER [COUNT] [CLM3D]
#
# COUNT defaults to 200, CLM3D to build/release/bin/clm3d. With INIT_DIR set (e.g. to the photo
# folder of LFPW, whose STEM.pts sit beside the photos) every fit starts from those points instead
# of the face detector (`--init-dir` / `--init`). Outputs go to a temporary folder that is removed
# at the end. Wall-clock figures depend on the machine and its load (printed too).
set -euo pipefail

[ $# -ge 2 ] || {
  echo "usage: $0 MODEL PHOTO_FOLDER [COUNT] [CLM3D]" >&2
  exit 2
}
model=$1
photos=$2
count=${3:-200}
clm3d=${4:-build/release/bin/clm3d}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
find "$photos" -maxdepth 1 -type f \( -iname '*.jpg' -o -iname '*.png' \) | sort | head -n "$count" >"$work/job.txt"
count=$(wc -l <"$work/job.txt")
[ "$count" -gt 0 ] || {
  echo "$photos: no .jpg or .png" >&2
  exit 1
}

now() { date +%s.%N; }
rate() { python3 -c "print(f'{$count / ($1) * 60:.1f}')"; }
load() { cut -d' ' -f1-3 /proc/loadavg; }

echo "machine: $(nproc) cores, load average before: $(load)" >&2
batch_init=()
[ -n "${INIT_DIR:-}" ] && batch_init=(--init-dir "$INIT_DIR")
declare -A seconds
for threads in 1 2; do
  begin=$(now)
  "$clm3d" batch --quiet --threads "$threads" --model "$model" --input "$work/job.txt" \
    "${batch_init[@]}" --out-dir "$work/batch-$threads" >/dev/null || true
  seconds[$threads]=$(python3 -c "print(f'{$(now) - $begin:.1f}')")
  echo "batch, $threads thread(s): ${seconds[$threads]} s" >&2
done
mkdir -p "$work/fit"
begin=$(now)
while read -r photo; do
  fit_init=()
  [ -n "${INIT_DIR:-}" ] && fit_init=(--init "$INIT_DIR/$(basename "${photo%.*}").pts")
  "$clm3d" fit --model "$model" --image "$photo" "${fit_init[@]}" --out "$work/fit/$(basename "${photo%.*}").pts" \
    >/dev/null 2>&1 || true
done <"$work/job.txt"
seconds[fit]=$(python3 -c "print(f'{$(now) - $begin:.1f}')")
echo "$count clm3d fit processes: ${seconds[fit]} s; load average after: $(load)" >&2

# The points must not depend on the way they were run.
same=yes
for pts in "$work"/fit/*.pts; do
  cmp -s "$pts" "$work/batch-1/$(basename "$pts")" || same=no
  cmp -s "$pts" "$work/batch-2/$(basename "$pts")" || same=no
done

echo "| run ($count photos) | wall time (s) | photos per minute | vs $count fit processes |"
echo "|---|---|---|---|"
echo "| $count \`clm3d fit\` processes | ${seconds[fit]} | $(rate "${seconds[fit]}") | 1.0x |"
for threads in 1 2; do
  echo "| one \`clm3d batch\`, --threads $threads | ${seconds[$threads]} | $(rate "${seconds[$threads]}") |" \
    "$(python3 -c "print(f'{${seconds[fit]} / ${seconds[$threads]}:.1f}x')") |"
done
echo "points identical in the three runs: $same"
