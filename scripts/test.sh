#!/usr/bin/env bash
# Quick start, command 2: install what is needed, build, and pass the whole test suite:
# the libFuzzer targets for a bounded time, the unit tests under ASan+UBSan, then every test of
# the release build (ctest's summary is the last thing printed).
# Environment: CLM3D_FUZZ_SECONDS (default 30 per target), CLM3D_SKIP_SANITIZERS=1 to skip the
# ASan+UBSan pass and the fuzzers when iterating locally.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

bash packaging/install-deps.sh

if [ "${CLM3D_SKIP_SANITIZERS:-0}" != "1" ]; then
  echo "== fuzz: building libFuzzer targets (clang, ASan+UBSan)"
  cmake --preset fuzz > /dev/null
  cmake --build --preset fuzz -j "$jobs"
  bash scripts/run-fuzzers.sh build/fuzz "${CLM3D_FUZZ_SECONDS:-30}"

  echo "== asan: unit tests under AddressSanitizer and UndefinedBehaviorSanitizer"
  cmake --preset asan -DCLM3D_WERROR=ON > /dev/null
  cmake --build --preset asan -j "$jobs"
  ctest --preset asan -j "$jobs" -L unit
fi

echo "== release: every test"
cmake --preset release -DCLM3D_WERROR=ON > /dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"
