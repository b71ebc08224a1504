#!/usr/bin/env bash
# Runs every libFuzzer target of a CLM3D_FUZZ build for SECONDS each, starting from a copy of its
# seed corpus (tests/fuzz/corpus/<target>/) in a temporary folder, so the repository is never
# modified. Prints one summary line per target; exits 1 if any target crashed, leaked, timed out
# or could not run. Crash inputs are kept in the artefact folder named in the summary.
# CLM3D_FUZZ_JOBS targets run at once (default: the number of cores): each fuzzer is one process
# on one core, so on 2 cores the 8 targets take 4 x SECONDS instead of 8 x SECONDS, each still
# fuzzing for SECONDS.
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
# The sanitizer runtimes of gcc <= 13 and LLVM <= 16 misread a dynamic TLS block that happens to
# sit at a certain page offset as an old-glibc header, and LeakSanitizer's tracer then crashes at
# exit ("Tracer caught signal 11") after a clean run. Not intercepting __tls_get_addr avoids it.
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}intercept_tls_get_addr=0
targets=(fuzz_pts fuzz_ljson fuzz_landmark_csv fuzz_scheme_json fuzz_model_file fuzz_project
  fuzz_manifest fuzz_tracks_csv)

jobs=${CLM3D_FUZZ_JOBS:-$(nproc)}
if ! [[ $jobs =~ ^[0-9]+$ ]] || [[ $jobs -lt 1 ]]; then
  echo "$0: CLM3D_FUZZ_JOBS must be a positive integer, not '$jobs'" >&2
  exit 2
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/clm3d-fuzz.XXXXXX")

# fuzz_one TARGET: fuzzes TARGET and writes its summary line to $work/TARGET/summary.txt; returns
# non-zero if it failed.
fuzz_one() {
  local target=$1 binary="$build_dir/bin/$1" corpus="$work/$1/corpus" artefacts="$work/$1/artefacts"
  local log="$work/$1/log.txt" summary_file="$work/$1/summary.txt" status runs coverage
  mkdir -p "$corpus" "$artefacts"
  if [[ ! -x $binary ]]; then
    echo "$target: MISSING ($binary not built; configure with -DCLM3D_FUZZ=ON)" >"$summary_file"
    return 1
  fi
  if [[ -d $source_dir/tests/fuzz/corpus/$target ]]; then
    cp "$source_dir/tests/fuzz/corpus/$target"/* "$corpus"/ 2>/dev/null
  fi
  # -rss_limit_mb and -timeout turn unbounded allocation and hangs into failures.
  "$binary" "$corpus" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -artifact_prefix="$artefacts/" >"$log" 2>&1
  status=$?
  runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
  coverage=$(grep -oE ' cov: [0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
  if [[ $status -ne 0 ]]; then
    echo "$target: FAILED (exit $status) after ${runs:-?} executions; log $log, inputs in $artefacts" >"$summary_file"
    return 1
  fi
  echo "$target: ok, ${runs:-?} executions in ${seconds} s, coverage ${coverage:-?} edges" >"$summary_file"
}

failed=0
running=0
for target in "${targets[@]}"; do
  if [[ $running -ge $jobs ]]; then
    wait -n || failed=1
    running=$((running - 1))
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
while [[ $running -gt 0 ]]; do
  wait -n || failed=1
  running=$((running - 1))
done

summary=()
for target in "${targets[@]}"; do
  summary+=("$(cat "$work/$target/summary.txt" 2>/dev/null || echo "$target: FAILED (no summary)")")
  [[ -f $work/$target/summary.txt ]] || failed=1
done

printf '%s\n' "${summary[@]}"
if [[ $failed -eq 0 ]]; then
  rm -rf "$work"
else
  echo "fuzzing found problems; logs kept in $work" >&2
fi
exit $failed
