#!/usr/bin/env bash
# Quick start, command 2: install what is needed, build, and pass the whole test suite:
# the libFuzzer targets for a bounded time, the unit tests under ASan+UBSan, the threaded training,
# loading and tracking tests under ThreadSanitizer, then every test of the release build (with the
# benchmarks run briefly, label bench) and the Debian package installed into a temporary root and
# run. Each stage prints its wall time, and a table of them ends the run (docs/testing.md lists
# them and where the time goes; CI must stay under 45 minutes on 2 cores).
# Environment: CLM3D_FUZZ_SECONDS (default 10 per target), CLM3D_FUZZ_JOBS (fuzzers run at once,
# default the number of cores), CLM3D_SKIP_SANITIZERS=1 to skip the fuzzers and the ASan and TSan
# passes when iterating locally.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

stage_names=()
stage_times=()
run_start=$SECONDS
# stage NAME COMMAND...: runs COMMAND and records its wall time.
stage() {
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  stage_names+=("$name")
  stage_times+=($((SECONDS - start)))
  echo "== $name: $((SECONDS - start)) s"
}
report_times() {
  local status=$? i
  echo "== stage times (s)"
  for i in "${!stage_names[@]}"; do printf '%6d  %s\n' "${stage_times[$i]}" "${stage_names[$i]}"; done
  printf '%6d  total%s\n' $((SECONDS - run_start)) "$([[ $status -eq 0 ]] || echo ", stopped by a failure")"
  slurm_line
}
# Whether the Slurm test (tests/slurm) ran or why it skipped: its verdict file, written by the test
# itself during the release tests (ctest shows a skip without its reason).
slurm_status=build/release/slurm-test-status.txt
slurm_line() {
  [ "${release_tests_started:-0}" = 1 ] || return 0
  if [ -f "$slurm_status" ]; then
    echo "== Slurm test: $(cat "$slurm_status")"
  else
    echo "== Slurm test: no verdict (it did not run, or stopped before starting Slurm)"
  fi
}
trap report_times EXIT

stage "dependencies" bash packaging/install-deps.sh

if [ "${CLM3D_SKIP_SANITIZERS:-0}" != "1" ]; then
  stage "fuzz build (clang, libFuzzer, ASan+UBSan)" \
    bash -c 'cmake --preset fuzz > /dev/null && cmake --build --preset fuzz -j "$1"' _ "$jobs"
  stage "fuzz run" bash scripts/run-fuzzers.sh build/fuzz "${CLM3D_FUZZ_SECONDS:-10}"

  stage "asan build (unit tests)" bash -c 'cmake --preset asan -DCLM3D_WERROR=ON > /dev/null &&
    cmake --build --preset asan -j "$1" --target clm3d_unit_tests' _ "$jobs"
  # Label slow (tests/CMakeLists.txt): the unit tests over 10 s each unoptimised under ASan; the
  # release pass runs them, and the tsan pass the threaded training and tracking among them.
  stage "asan tests (unit, ASan+UBSan)" ctest --preset asan -j "$jobs" -L unit -LE slow

  # Warnings are not errors here: gcc 12 at -O1 with -fsanitize=thread reports false -Warray-bounds
  # on std::string concatenations inside libstdc++ (seen in option_table.cpp and manifest_test.cpp).
  # The release build, with every file, is the warnings gate.
  stage "tsan build (threaded tests)" bash -c 'cmake --preset tsan -DCLM3D_WERROR=OFF > /dev/null &&
    cmake --build --preset tsan -j "$1" --target clm3d_tsan_tests' _ "$jobs"
  stage "tsan tests (training, loading, tracking)" ctest --preset tsan -j "$jobs"
fi

stage "release build" bash -c 'cmake --preset release -DCLM3D_WERROR=ON > /dev/null &&
  cmake --build --preset release -j "$1"' _ "$jobs"
stage "package (cpack -G DEB, install into a temporary root, run)" bash scripts/package-test.sh build/release
rm -f "$slurm_status"
release_tests_started=1
if [ "${CLM3D_SKIP_SANITIZERS:-0}" != "1" ]; then
  # The unit tests the asan pass ran are not run again: every other test (command line, GUI,
  # real faces, benchmarks, Slurm) and the unit tests labelled slow, which only this pass runs.
  release_tests() {
    ctest --preset release -j "$jobs" -LE unit && ctest --preset release -j "$jobs" -L slow
  }
  stage "release tests (all but the unit tests the asan pass ran)" release_tests
else
  stage "release tests (every test)" ctest --preset release -j "$jobs"
fi
