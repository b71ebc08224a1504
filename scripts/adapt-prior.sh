#!/usr/bin/env bash
# How clm3d adapt's default --prior and --refiner-prior were chosen (docs/adapt.md, "Chosen on
# real video"): the correction benchmark's review-adapt strategy on the two webcam clips of
# ../shared/data/videos (cap12, cap13: not in the benchmark's sequences, nor in any training), with
# dlib's points as the stand-in truth, once per prior.
#
# Usage: scripts/adapt-prior.sh MODEL [OUT]   (default OUT adapt-prior-out)
# Environment: PRIOR_OPTION (default --prior; --refiner-prior for the point refiner's), PRIORS
# (default "10 30 100 300"), and what scripts/correction-bench.sh reads.
# The clips are research-only: OUT holds dlib's points on them, never commit it.
set -euo pipefail
cd "$(dirname "$0")/.."
MODEL=${1:?usage: scripts/adapt-prior.sh MODEL [OUT]}
OUT=${2:-adapt-prior-out}
OPTION=${PRIOR_OPTION:---prior}
for prior in ${PRIORS:-10 30 100 300}; do
  echo "== $OPTION $prior"
  SEQUENCES="cap12 cap13" \
    BENCH_OPTIONS="--strategies review-adapt --max-corrections 100 $OPTION $prior" \
    bash scripts/correction-bench.sh "$MODEL" "$OUT" 2> "$OUT$OPTION-$prior.err" |
    grep -E '^\| (cap1|sequence|---)' || true
done
