#!/usr/bin/env bash
# Quick start, command 1: install what is needed, build the command line and the studio, run the
# demo into ./demo-out (or the folder given with --out), then open the studio on it: the demo's
# folder is a clm3d project, and the studio opens it with the test video tracked (the demo's
# track), compared with its exact ground truth, and the evaluation on the Evaluate page. With no
# display (or CLM3D_OPEN_STUDIO=0) it prints the command that opens it, and how to take a
# screenshot without a display. Arguments go to `clm3d demo` (e.g. --real, docs/studio.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh release --target clm3d clm3d-studio
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
if [ "${CLM3D_OPEN_STUDIO:-1}" != "0" ] && { [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; }; then
  echo "Opening the demo project in clm3d-studio ($studio --demo $out --page track)"
  "$studio" --demo "$out" --page track
else
  echo "No display here (or CLM3D_OPEN_STUDIO=0). To look at the demo in clm3d-studio:"
  echo "  on a machine with a display:  $studio --demo $out --page track"
  echo "  as a picture, without one:    xvfb-run -a -s '-screen 0 1920x1200x24' $studio --demo $out --page track --screenshot demo-studio.png"
fi
