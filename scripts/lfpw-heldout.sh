#!/usr/bin/env bash
# Writes resources/datasets/lfpw-train-heldout.txt: the 100 LFPW training photos held out of
# training while the defaults of docs/real-faces.md, docs/training.md and docs/fitting.md were
# chosen. They are the last 100 of the 805 in name order (image_0767 .. image_0871); the models
# those choices were measured with trained on the other 705, the first 705 in name order, which is
# resources/datasets/real-705.json (real.json with the photos source's "limit": 705).
#
# Usage: scripts/lfpw-heldout.sh [--check]   (--check: fail when the committed list differs)
# Environment: CLM3D_DATA (default ../shared/data).
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=${CLM3D_DATA:-$PWD/../shared/data}
TRAIN=$DATA/photos/lfpw/train
LIST=resources/datasets/lfpw-train-heldout.txt
[[ -d $TRAIN ]] || { echo "lfpw-heldout: no LFPW training photos in $TRAIN" >&2; exit 1; }
count=$(find "$TRAIN" -maxdepth 1 -name '*.jpg' | wc -l)
[[ $count -eq 805 ]] || { echo "lfpw-heldout: $TRAIN holds $count photos, expected 805" >&2; exit 1; }
new=$(mktemp)
trap 'rm -f "$new"' EXIT
{
  echo "# The 100 LFPW training photos held out of training while defaults were chosen: the last"
  echo "# 100 of the 805 in name order (written by scripts/lfpw-heldout.sh; paths relative to this"
  echo "# folder, as in real.json). Train on resources/datasets/real-705.json, fit these with"
  echo "# clm3d fit --images resources/datasets/lfpw-train-heldout.txt."
  find "$TRAIN" -maxdepth 1 -name '*.jpg' -printf '%f\n' | LC_ALL=C sort | tail -n 100 |
    sed 's|^|../../../shared/data/photos/lfpw/train/|'
} >"$new"
if [[ ${1:-} == --check ]]; then
  diff -u "$LIST" "$new" && echo "lfpw-heldout: $LIST is up to date"
else
  mv "$new" "$LIST"
  echo "lfpw-heldout: wrote $LIST ($(grep -vc '^#' "$LIST") photos)"
fi
