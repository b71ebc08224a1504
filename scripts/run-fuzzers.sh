#!/usr/bin/env bash
# Runs every libFuzzer target of a CLM3D_FUZZ build for SECONDS each, starting from a copy of its
# seed corpus (tests/fuzz/corpus/<target>/) in a temporary folder, so the repository is never
# modified. Prints one summary line per target; exits 1 if any target crashed, leaked, timed out
# or could not run. Crash inputs are kept in the artefact folder named in the summary.
#
#   scripts/run-fuzzers.sh BUILD_DIR SECONDS
set -u

if [[ $# -ne 2 ]]; then
  echo "usage: $0 BUILD_DIR SECONDS" >&2
  exit 2
fi
build_dir=$1
seconds=$2
if ! [[ $seconds =~ ^[0-9]+$ ]] || [[ $seconds -lt 1 ]]; then
  echo "$0: SECONDS must be a positive integer, not '$seconds'" >&2
  exit 2
fi
source_dir=$(cd "$(dirname "$0")/.." && pwd)
targets=(fuzz_pts fuzz_ljson fuzz_landmark_csv fuzz_scheme_json fuzz_model_file fuzz_project
  fuzz_manifest fuzz_tracks_csv)

work=$(mktemp -d "${TMPDIR:-/tmp}/clm3d-fuzz.XXXXXX")
failed=0
summary=()
for target in "${targets[@]}"; do
  binary="$build_dir/bin/$target"
  if [[ ! -x $binary ]]; then
    summary+=("$target: MISSING ($binary not built; configure with -DCLM3D_FUZZ=ON)")
    failed=1
    continue
  fi
  corpus="$work/$target/corpus"
  artefacts="$work/$target/artefacts"
  mkdir -p "$corpus" "$artefacts"
  if [[ -d $source_dir/tests/fuzz/corpus/$target ]]; then
    cp "$source_dir/tests/fuzz/corpus/$target"/* "$corpus"/ 2>/dev/null
  fi
  log="$work/$target/log.txt"
  # -rss_limit_mb and -timeout turn unbounded allocation and hangs into failures.
  "$binary" "$corpus" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$artefacts/" >"$log" 2>&1
  status=$?
  runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
  coverage=$(grep -oE ' cov: [0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
  if [[ $status -ne 0 ]]; then
    summary+=("$target: FAILED (exit $status) after ${runs:-?} executions; log $log, inputs in $artefacts")
    failed=1
  else
    summary+=("$target: ok, ${runs:-?} executions in ${seconds} s, coverage ${coverage:-?} edges")
  fi
done

printf '%s\n' "${summary[@]}"
if [[ $failed -eq 0 ]]; then
  rm -rf "$work"
else
  echo "fuzzing found problems; logs kept in $work" >&2
fi
exit $failed
