#!/usr/bin/env bash
# Quick start, command 1: install what is needed, build, and run the demo into ./demo-out (or the
# folder given with --out). The demo's folder is a clm3d project: afterwards, when a display exists
# and clm3d-studio is built, the studio opens it (set CLM3D_OPEN_STUDIO=0 not to); otherwise the
# command that opens it is printed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release --target clm3d
./build/release/bin/clm3d demo --out demo-out "$@"

out=demo-out
previous=
for argument in "$@"; do
  case "$argument" in
    --out=*) out=${argument#--out=} ;;
    *) if [ "$previous" = "--out" ]; then out=$argument; fi ;;
  esac
  previous=$argument
done

studio=./build/release/bin/clm3d-studio
echo
if [ ! -x "$studio" ]; then
  echo "To look at the demo in clm3d-studio: cmake --build build/release --target clm3d-studio," \
       "then $studio --demo $out"
elif [ "${CLM3D_OPEN_STUDIO:-1}" != "0" ] && { [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; }; then
  echo "Opening the demo project in clm3d-studio ($studio --demo $out)"
  "$studio" --demo "$out"
else
  echo "To look at the demo in clm3d-studio (needs a display): $studio --demo $out"
fi
