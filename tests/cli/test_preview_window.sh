#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint preview with its window (OpenCV highgui, trackbars) under a virtual X server: 60
# frames of a rendered clip at the clip's pace, the last picture saved and checked against the
# truth as the headless one is (test_preview_cli.sh). Skipped (77) without xvfb-run.
# usage: test_preview_window.sh RAYPOINT RENDER_SCENE CHECK_VIEW
set -u
raypoint=$1
render=$2
check=$3
command -v xvfb-run >/dev/null || { echo "xvfb-run not found (apt-get install xvfb xauth): skipped"; exit 77; }
. "$(dirname "$0")/common.sh"
chmod 700 "$work"
export XDG_CONFIG_HOME="$work/config" XDG_CONFIG_DIRS="$work/none" XDG_RUNTIME_DIR="$work"
# In a sanitizer build: the window toolkit's own allocations kept until exit are not ours.
export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$(cd "$(dirname "$0")" && pwd)/gui-leaks.supp"

"$render" --preset ideal --seconds 4 --fps 15 --out "$work/ideal" --no-masks >/dev/null || { echo "cannot render"; exit 1; }
timeout 120 xvfb-run -a "$raypoint" preview --input "$work/ideal/video.mp4" --frames 60 --screenshot "$work/shot.png" > "$work/out.txt" 2>&1 || fail "preview exited $?: $(cat "$work/out.txt")"
grep -q "w write $work/config/raypoint/raypoint.ini" "$work/out.txt" || fail "no key help: $(cat "$work/out.txt")"
truth=$(sed -n 60p "$work/ideal/truth.jsonl")
cx=$(echo "$truth" | sed -E 's/.*"centroid": ?\[([-0-9.]+), ?([-0-9.]+)\].*/\1/')
cy=$(echo "$truth" | sed -E 's/.*"centroid": ?\[([-0-9.]+), ?([-0-9.]+)\].*/\2/')
"$check" screenshot "$work/shot.png" "$cx" "$cy" tracking || fail "the window's picture is wrong"
"$check" screenshot "$work/shot.png" "$cx" "$cy" recovering >/dev/null && fail "a wrong state text passed"

[ "$failures" -eq 0 ] || exit 1
echo "preview_window: all checks passed"
