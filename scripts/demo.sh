#!/usr/bin/env bash
# Quick start, command 1: install what is needed, build, and run the demo into ./demo-out.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release --target clm3d
./build/release/bin/clm3d demo --out demo-out "$@"
