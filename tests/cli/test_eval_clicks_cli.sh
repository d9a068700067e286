#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint eval-clicks --trace end to end on the CI gesture subset: one header and one line a
# frame for the clip named, in the documented columns, with the presses that went out; the
# target pushes and gestures split by hand and ball, adding up; a name
# that is no clip answered with one line on stderr before anything is tracked. Then a recorded
# clip with its truth file: motion and approach spans scored as docs/clicks.md says.
# usage: test_eval_clicks_cli.sh RAYPOINT
set -u
raypoint=$1
. "$(dirname "$0")/common.sh"

expect_error 2 "--trace nosuch: no clip of that name" eval-clicks --set-name ci --trace nosuch
mkdir -p "$work/no-photos"
expect_error 1 "--backgrounds $work/no-photos: no photographs there" \
  eval-clicks --set-name ci --backgrounds "$work/no-photos"
expect_error 1 "--backgrounds $work/missing: cannot list the folder" \
  eval-clicks --set-name ci --backgrounds "$work/missing"

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
pattern="^$number (- - -|$number $number $number) $number [-+]$number (absorbed|given_back|-) -?$number -?$number $state( [-+](left|right|middle))*( wheel -?[0-9]+)?$"
bad=$(grep -Evc "$pattern" "$work/frames.txt")
[ "$bad" -eq 0 ] || fail "$bad lines do not match the columns, e.g. $(grep -Ev "$pattern" "$work/frames.txt" | head -1)"
awk 'NR > 1 && $1 <= last { bad = 1 } { last = $1 } END { exit bad }' "$work/frames.txt" ||
  fail "times do not increase"
# The target pushes and each gesture by what makes them: the subset holds hands and balls, and
# a split's rows add up to the whole, count and recognised alike.
count() { grep -F "| $1 |" "$work/out.txt" | cut -d'|' -f3 | tr -d ' '; }
found() { grep -F "| $1 |" "$work/out.txt" | cut -d'|' -f4 | sed -E 's/.*\(([0-9]+)\/.*/\1/'; }
for row in target scroll; do
  hand=$(count "$row (hand)")
  sphere=$(count "$row (sphere)")
  [ -n "$hand" ] && [ -n "$sphere" ] || fail "no '$row (hand)' and '$row (sphere)' rows"
  [ "$((${hand:-0} + ${sphere:-0}))" -eq "$(count "$row")" ] ||
    fail "$row: hand $hand + sphere $sphere is not $(count "$row")"
  hand=$(found "$row (hand)")
  sphere=$(found "$row (sphere)")
  [ "$((${hand:-0} + ${sphere:-0}))" -eq "$(found "$row")" ] ||
    fail "$row: the split's pressed or recognised do not add up"
done
grep -Eq '^\| [a-z ]+ \((hand|sphere)\) \| 0 \|' "$work/out.txt" && fail "a split row with no gesture"
grep -q ' pressed +left$' "$work/frames.txt" || fail "no left press in push-000's trace"
grep -q ' -left$' "$work/frames.txt" || fail "no left release in push-000's trace"

# A recorded clip's truth: its three pushes as non-push motion are three false clicks; as an
# approach (a push not meant), none, and the approach is counted pressed.
timeout 240 "$raypoint" eval-clicks --set-name ci --write "$work/clip" --trace push-000 \
  > /dev/null 2>&1 || fail "eval-clicks --write exited $?"
clip=$work/clip/push-000.mp4
printf 'motion 0 30\n' > "$clip.clicks"
"$raypoint" eval-clicks --set-name none "$clip" > "$work/motion.txt" 2>&1 ||
  fail "eval-clicks on a recorded clip exited $?"
grep -Eq '^\| all \|.*\| 3 \| [0-9.]+ \|$' "$work/motion.txt" ||
  fail "expected 3 false clicks: $(grep '^| all' "$work/motion.txt")"
printf 'approach 0 30 # the pushes, unmeant\n' > "$clip.clicks"
"$raypoint" eval-clicks --set-name none "$clip" > "$work/approach.txt" 2>&1 ||
  fail "eval-clicks on a recorded clip exited $?"
grep -Eq '^\| all \|.*\| 0 \| - \|$' "$work/approach.txt" ||
  fail "expected no false click: $(grep '^| all' "$work/approach.txt")"
grep -q '^| approaches as fast as a push in non-push motion, pressed | 1 | 100.0% (1/1) |' \
  "$work/approach.txt" || fail "expected the approach pressed: $(grep approach "$work/approach.txt")"
grep -Eq '\((hand|sphere)\) \|' "$work/approach.txt" &&
  fail "a recorded clip says nothing of its target, yet split rows: $(grep -E '\((hand|sphere)\)' "$work/approach.txt")"
printf 'approach 5 4\n' > "$clip.clicks"
expect_error 1 "approach: expected FROM TO in seconds, FROM < TO" eval-clicks --set-name none "$clip"

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "raypoint eval-clicks --trace: all checks passed"
