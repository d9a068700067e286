#!/bin/bash
# SPDX-License-Identifier: MIT
# The pictures end to end on rendered clips: `preview --headless` against the truth (the
# centroid marker within 3 px of the true centroid, the state text of the tracker's state), `plot`
# and `track --plot` against the track, `setup --headless` on a push clip (its press_rise clicks
# on the pushes, the INI keeps its comments and order). Each check is also shown to fail on a
# wrong expectation, so a checker that accepts anything fails here.
# usage: test_preview_cli.sh RAYPOINT RENDER_SCENE CHECK_VIEW
set -u
raypoint=$1
render=$2
check=$3
. "$(dirname "$0")/common.sh"
# No user configuration and no daemon to pause.
export XDG_CONFIG_HOME="$work/config" XDG_CONFIG_DIRS="$work/none" XDG_RUNTIME_DIR="$work"

"$render" --preset ideal --seconds 4 --fps 15 --out "$work/ideal" --no-masks >/dev/null || { echo "cannot render"; exit 1; }
clip="$work/ideal/video.mp4"

# preview: 60 frames (4 s at 15 fps: past the 2 s start-up), the last one saved.
timeout 120 "$raypoint" preview --input "$clip" --headless --frames 60 --screenshot "$work/shot.png" > "$work/preview.txt" 2>&1 || fail "preview exited $?: $(cat "$work/preview.txt")"
[ -s "$work/shot.png" ] || fail "no screenshot"
grep -q "60 frames" "$work/preview.txt" || fail "preview: $(cat "$work/preview.txt")"
timeout 60 "$raypoint" track "$clip" > "$work/track.jsonl" || fail "track exited $?"
state=$(sed -n 60p "$work/track.jsonl" | sed -E 's/.*"state":"([a-z]+)".*/\1/')
truth=$(sed -n 60p "$work/ideal/truth.jsonl")
cx=$(echo "$truth" | sed -E 's/.*"centroid": ?\[([-0-9.]+), ?([-0-9.]+)\].*/\1/')
cy=$(echo "$truth" | sed -E 's/.*"centroid": ?\[([-0-9.]+), ?([-0-9.]+)\].*/\2/')
[ "$state" = tracking ] || fail "frame 59 is $state on the ideal clip, not tracking"
"$check" screenshot "$work/shot.png" "$cx" "$cy" "$state" || fail "the screenshot's overlay is wrong"
# A wrong truth or state fails: 10 px off at 640 wide, another state's name.
"$check" screenshot "$work/shot.png" "$(awk -v x="$cx" 'BEGIN { print x + 0.016 }')" "$cy" "$state" >/dev/null && fail "a centroid 10 px off passed"
"$check" screenshot "$work/shot.png" "$cx" "$cy" searching >/dev/null && fail "a wrong state text passed"

# plot and track --plot: the series where the track puts them, for this track and no other.
timeout 60 "$raypoint" track "$clip" --plot "$work/plot1.png" > "$work/track2.jsonl" || fail "track --plot exited $?"
"$check" plot "$work/plot1.png" "$work/track2.jsonl" || fail "track --plot does not follow the track"
timeout 60 "$raypoint" plot "$work/track.jsonl" -o "$work/plot2.png" || fail "plot exited $?"
"$check" plot "$work/plot2.png" "$work/track.jsonl" || fail "plot does not follow the track"
size=$(stat -c %s "$work/plot2.png")
[ "$size" -lt 100000 ] || fail "plot is $size bytes"

# setup on a push clip: proposes, tries, writes the INI keeping its comments and order.
"$render" --preset push --out "$work/push" --no-masks >/dev/null || fail "cannot render push"
push="$work/push/video.mp4"
timeout 60 "$raypoint" track "$push" > "$work/push.jsonl" || fail "track push exited $?"
"$check" plot "$work/plot2.png" "$work/push.jsonl" >/dev/null && fail "a plot passed for another track"
cat > "$work/user.ini" <<'INI'
# my settings: keep this comment
[click]
; the release first, on purpose
release_rise = 0.07
press_rise = 0.9   # far too deep: setup must lower it

[tracking]
min_area = 0.01
INI
timeout 300 "$raypoint" setup --input "$push" --headless --config "$work/user.ini" > "$work/setup.txt" 2>&1 || fail "setup exited $?: $(cat "$work/setup.txt")"
grep -q "^wrote 7 settings" "$work/setup.txt" || fail "setup did not write: $(cat "$work/setup.txt")"
head -5 "$work/user.ini" | grep -q "^# my settings: keep this comment$" || fail "first comment lost"
grep -n "" "$work/user.ini" | grep -q "^3:; the release first, on purpose$" || fail "comment moved: $(cat "$work/user.ini")"
grep -q "^release_rise = " "$work/user.ini" && [ "$(grep -n '^release_rise' "$work/user.ini" | cut -d: -f1)" -eq 4 ] || fail "release_rise moved"
grep -q "^press_rise = 0\.[0-9]* # far too deep: setup must lower it$" "$work/user.ini" || fail "press_rise line: $(grep press_rise "$work/user.ini")"
grep -q "^press_rise = 0.9 " "$work/user.ini" && fail "press_rise not changed"
grep -q "^min_area = 0.01$" "$work/user.ini" || fail "an untouched key changed"
grep -q "^\[pointer\]" "$work/user.ini" || fail "no [pointer] section added"
"$raypoint" check-config "$work/user.ini" >/dev/null || fail "the written INI does not check"
# Its press_rise clicks on the clip's two pushes in the daemon itself; 0.9 clicked on none.
timeout 120 "$raypoint" run --input "$push" --unpaced --sink "file:$work/ev.txt" --no-control --config "$work/user.ini" >/dev/null 2>&1 || fail "run exited $?"
presses=$(grep -c "EV_KEY BTN_LEFT 1" "$work/ev.txt")
[ "$presses" -eq 2 ] || fail "the proposal pressed $presses times on 2 pushes"
# The plot takes the clicks from those events.
timeout 60 "$raypoint" plot "$work/push.jsonl" --events "$work/ev.txt" -o "$work/push.png" || fail "plot --events exited $?"

# With a daemon running, preview on a camera pauses it first and resumes it however it ends:
# here the camera does not exist. The clip loops (--realtime) so the daemon outlives the checks
# on a slow or loaded machine.
"$raypoint" run --input "$push" --realtime --duration 240 --sink null 2>"$work/daemon.log" &
daemon_pid=$!
trap 'kill "$daemon_pid" 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 50); do [ -S "$work/raypoint.sock" ] && break; sleep 0.1; done
timeout 30 "$raypoint" preview --camera "$work/video9" --headless --frames 1 2>"$work/err.txt" && fail "preview on a missing camera succeeded"
grep -q "paused the running daemon" "$work/err.txt" || fail "no pause: $(cat "$work/err.txt")"
grep -q "$work/video9" "$work/err.txt" || fail "the camera error does not name it: $(cat "$work/err.txt")"
grep -q "resumed the daemon" "$work/err.txt" || fail "no resume: $(cat "$work/err.txt")"
"$raypoint" ctl status | grep -q '^paused: no' || fail "the daemon stayed paused"
kill -TERM "$daemon_pid"
wait "$daemon_pid"

# Bad input: one line, the right exit code.
expect_error 1 "$work/missing.jsonl: cannot open" plot "$work/missing.jsonl" -o "$work/x.png"
expect_error 2 "missing -o OUT.png" plot "$work/track.jsonl"
echo "not json" > "$work/bad.jsonl"
expect_error 1 "$work/bad.jsonl:1: no \"t\"" plot "$work/bad.jsonl" -o "$work/x.png"
expect_error 2 "--frames 0: not a frame count" preview --input "$clip" --headless --frames 0
expect_error 1 "$work/nowhere/s.png: cannot write" preview --input "$clip" --headless --frames 2 --screenshot "$work/nowhere/s.png"

[ "$failures" -eq 0 ] || exit 1
echo "preview_cli: all checks passed"
