#!/usr/bin/env bash
# Runs one of the measurements behind constants of core (tests/measure/): programs that print
# figures and assert nothing, so they are not part of the test suite (scripts/test.sh). Builds the
# program in the release preset if needed. Extra arguments go to the program (GoogleTest flags,
# e.g. --gtest_filter='BoxCalibration.Timing').
#
#   scripts/measure.sh boxes [ARGS]              detector box calibration, variants and timing
#                                                (docs/initialisation.md; 20-25 minutes)
#   scripts/measure.sh expert-confidence [ARGS]  rlms confidences of faces and non-faces, the
#                                                visibility rule (docs/tracking.md; env
#                                                CLM3D_MEASURE_MODEL, CLM3D_MEASURE_HEAD_SEED,
#                                                CLM3D_MEASURE_SMALL)
#   scripts/measure.sh track-speed [ARGS]        where clm3d track's time goes: model load, decode,
#                                                detection, search, refinement, writing
#                                                (docs/tracking.md; env CLM3D_MEASURE_VIDEO,
#                                                CLM3D_MEASURE_MODEL)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  boxes) target=clm3d_measure_box_calibration ;;
  expert-confidence) target=clm3d_measure_expert_confidence ;;
  track-speed) target=clm3d_measure_track_speed ;;
  *)
    echo "usage: $0 boxes|expert-confidence|track-speed [GTEST_ARGS...]" >&2
    exit 2
    ;;
esac
shift
[[ -f build/release/build.ninja ]] || cmake --preset release > /dev/null
cmake --build --preset release --target "$target"
exec "build/release/bin/$target" "$@"
