#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint eval-clicks --trace end to end on the CI gesture subset: one header and one line a
# frame for the clip named, in the documented columns, with the presses that went out; a name
# that is no clip answered with one line on stderr before anything is tracked.
# usage: test_eval_clicks_cli.sh RAYPOINT
set -u
raypoint=$1
. "$(dirname "$0")/common.sh"

expect_error 2 "--trace nosuch: no clip of that name" eval-clicks --set-name ci --trace nosuch

timeout 240 "$raypoint" eval-clicks --set-name ci --jobs 2 --trace push-000 \
  > "$work/out.txt" 2> "$work/err.txt" || fail "eval-clicks --trace exited $?"
grep -q '^| all |' "$work/out.txt" || fail "no table on stdout"
[ "$(grep -c '^# trace push-000: ' "$work/err.txt")" -eq 1 ] ||
  fail "expected one header for push-000: $(grep '^#' "$work/err.txt" | head -3)"
grep -v '^#' "$work/err.txt" > "$work/frames.txt"
frames=$(wc -l < "$work/frames.txt")
# push-000 is a 30 fps clip of at least 8 s.
[ "$frames" -ge 240 ] || fail "$frames frame lines, expected one a frame"
number='[0-9]+\.[0-9]+'
state='(inactive|idle|rising|drifting|pressed|dragging|refractory|holding|right_armed|scrolling)'
pattern="^$number (- - -|$number $number $number) $number [-+]$number (absorbed|given_back|-) $state( [-+](left|right|middle))*( wheel -?[0-9]+)?$"
bad=$(grep -Evc "$pattern" "$work/frames.txt")
[ "$bad" -eq 0 ] || fail "$bad lines do not match the columns, e.g. $(grep -Ev "$pattern" "$work/frames.txt" | head -1)"
awk 'NR > 1 && $1 <= last { bad = 1 } { last = $1 } END { exit bad }' "$work/frames.txt" ||
  fail "times do not increase"
grep -q ' pressed +left$' "$work/frames.txt" || fail "no left press in push-000's trace"
grep -q ' -left$' "$work/frames.txt" || fail "no left release in push-000's trace"

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "raypoint eval-clicks --trace: all checks passed"
