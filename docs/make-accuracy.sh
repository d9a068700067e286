#!/bin/bash
# SPDX-License-Identifier: MIT
# Regenerates the table of docs/accuracy.md: raypoint's `track` beside OpenCV's CamShift and CSRT,
# scored by a scorer that reads scene folders (video.mp4, truth.jsonl, masks.npz; docs/scoring.md),
# on the clips given plus twelve presets rendered with four other seeds (7, 11, 13, 17), so that a default
# tuned on one rendering shows when it fails another of the same kind.
#   docs/make-accuracy.sh BUILD_DIR SCORER.py CLIP_DIR...
set -euo pipefail
build=$(realpath "$1"); scorer=$2; shift 2
renders=$(mktemp -d); trap 'rm -rf "$renders"' EXIT
for preset in realworld hd60 pause interfering nonconvex fast flicker person skinwall desk sleeve passer; do
  for seed in 7 11 13 17; do
    "$build/tests/scene/raypoint-render-scene" --preset "$preset" --seed "$seed" \
      --out "$renders/${preset}_$seed" >/dev/null
  done
done
# The scorer needs OpenCV's Python bindings (Debian: python3-opencv); its errors are shown.
table=$(python3 "$scorer" "$@" "$renders"/* --peers camshift,csrt \
          --raypoint "$build/raypoint track {video} --format jsonl" | grep -v '^{' || true)
[ -n "$table" ] || { echo "make-accuracy.sh: the scorer printed no table" >&2; exit 1; }
doc=$(dirname "$0")/accuracy.md
python3 - "$doc" "$table" <<'PY'
import sys
doc, table = sys.argv[1], sys.argv[2]
text = open(doc).read()
start, end = "<!-- table: make-accuracy.sh -->\n", "<!-- end of table -->\n"
head, rest = text.split(start)
_, tail = rest.split(end)
open(doc, "w").write(head + start + "```\n" + table.strip() + "\n```\n" + end + tail)
PY
