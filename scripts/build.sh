#!/usr/bin/env bash
# Installs the dependencies and builds a configure preset (default: release).
# Usage: scripts/build.sh [PRESET] [cmake --build args...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
shift || true
bash packaging/install-deps.sh
extra=()
if [ "${CLM3D_WERROR:-1}" = "1" ] && [ "$preset" != "fuzz" ]; then extra+=(-DCLM3D_WERROR=ON); fi
cmake --preset "$preset" "${extra[@]}" > /dev/null
cmake --build --preset "$preset" -j "$(nproc)" "$@"
