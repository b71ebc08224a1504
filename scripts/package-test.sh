#!/usr/bin/env bash
# Builds the Debian package of a release build (cpack -G DEB) and checks what a user would get:
# the .deb is under 20 MB, its binaries are stripped with their debug symbols in the separate
# clm3d-dbgsym package, and the clm3d it installs, unpacked into a temporary root (dpkg -x, no root
# rights needed), runs: `clm3d --help`, and `clm3d synth-head` with a contact sheet, which loads the
# packaged offscreen render module. Part of scripts/test.sh; prints one line per check.
#
#   scripts/package-test.sh [BUILD_DIR]   (default build/release, already built)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
limit_mb=20
work=$(mktemp -d "${TMPDIR:-/tmp}/clm3d-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() {
  echo "package: FAILED: $*" >&2
  exit 1
}

if ! (cd "$build" && cpack -G DEB -B "$work/pkg") >"$work/cpack.log" 2>&1; then
  cat "$work/cpack.log" >&2
  fail "cpack -G DEB in $build"
fi
deb=$(find "$work/pkg" -maxdepth 1 -name 'clm3d_*.deb' | head -1)
dbg=$(find "$work/pkg" -maxdepth 1 -name 'clm3d-dbgsym_*.*deb' | head -1)
[[ -n $deb ]] || fail "no clm3d_*.deb in $work/pkg"
[[ -n $dbg ]] || fail "no clm3d-dbgsym package beside $(basename "$deb")"
bytes=$(stat -c %s "$deb")
echo "package: $(basename "$deb") $((bytes / 1024)) KiB, $(basename "$dbg") $(($(stat -c %s "$dbg") / 1024)) KiB"
((bytes < limit_mb * 1024 * 1024)) || fail "$(basename "$deb") is over $limit_mb MB"

root=$work/root
dpkg -x "$deb" "$root"
for binary in "$root"/usr/bin/* "$root"/usr/lib/clm3d/*.so; do
  [[ -f $binary ]] || continue
  if readelf -S "$binary" | grep -q '\.debug_info'; then fail "$binary keeps its debug symbols"; fi
done
echo "package: installed $(du -sh "$root" | cut -f1) into a temporary root, binaries stripped"

"$root/usr/bin/clm3d" --help >"$work/help.txt" || fail "clm3d --help exited $?"
grep -q synth-head "$work/help.txt" || fail "clm3d --help does not list synth-head"
"$root/usr/bin/clm3d" synth-head --seed 3 --texture-size 256 --out "$work/heads" \
  --contact-sheet "$work/heads/sheet.png" --tile-size 64 >"$work/synth.txt" ||
  fail "clm3d synth-head exited $? ($(cat "$work/synth.txt"))"
for f in head-3.obj head-3.ljson sheet.png; do
  [[ -s $work/heads/$f ]] || fail "clm3d synth-head wrote no $f"
done
echo "package: the installed clm3d runs --help and synth-head (contact sheet rendered)"
