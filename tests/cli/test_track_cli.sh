#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint track end to end: a rendered clip through the real command, its JSONL and CSV output
# checked line by line, and every kind of bad input answered with one line on stderr naming the
# input and the reason, a non-zero exit, and no hang.
# usage: test_track_cli.sh RAYPOINT RENDER_SCENE
set -u
raypoint=$1
render=$2
. "$(dirname "$0")/common.sh"

"$render" --preset ideal --seconds 4 --out "$work/ideal" --no-masks >/dev/null || { echo "cannot render"; exit 1; }
clip="$work/ideal/video.mp4"
frames=$(wc -l < "$work/ideal/truth.jsonl")

# JSONL: exactly one object a frame, keys in the documented order, nothing else on stdout.
timeout 60 "$raypoint" track "$clip" --format jsonl > "$work/out.jsonl" 2> "$work/err.txt" || fail "track exited $?"
[ "$(wc -l < "$work/out.jsonl")" -eq "$frames" ] || fail "expected $frames lines, got $(wc -l < "$work/out.jsonl")"
[ ! -s "$work/err.txt" ] || fail "stderr not empty when not a terminal: $(head -1 "$work/err.txt")"
number='-?[0-9]+(\.[0-9]+)?'
pair="(null|\[$number,$number\])"
pattern="^\{\"frame\":[0-9]+,\"t\":$number,\"state\":\"(initializing|searching|tracking|validating|recovering)\",\"centroid\":$pair,\"area\":(null|$number),\"inner\":$pair,\"position\":(null|\[$number,$number,$number\]),\"movement\":[0-9]+,\"us\":[0-9]+\}$"
bad=$(grep -Evc "$pattern" "$work/out.jsonl")
[ "$bad" -eq 0 ] || fail "$bad lines do not match the JSONL schema, e.g. $(grep -Ev "$pattern" "$work/out.jsonl" | head -1)"
grep -q '"state":"tracking","centroid":\[' "$work/out.jsonl" || fail "the target was never tracked"
head -1 "$work/out.jsonl" | grep -q '"frame":0,"t":0.00000,"state":"initializing"' || fail "first line: $(head -1 "$work/out.jsonl")"
# Frame time comes from the container: frame 30 of a 30 fps clip is at 1 s.
sed -n 31p "$work/out.jsonl" | grep -q '"frame":30,"t":1.00000,' || fail "frame 30: $(sed -n 31p "$work/out.jsonl")"
# --fps overrides it.
timeout 60 "$raypoint" track "$clip" --fps 10 | sed -n 31p | grep -q '"t":3.00000,' || fail "--fps 10 did not set t"

# CSV: a header and one row a frame, same states as JSONL.
timeout 60 "$raypoint" track "$clip" --format csv > "$work/out.csv" || fail "csv exited $?"
[ "$(head -1 "$work/out.csv")" = "frame,t,state,cx,cy,area,ix,iy,px,py,pz,movement,us" ] || fail "csv header"
[ "$(($(wc -l < "$work/out.csv") - 1))" -eq "$frames" ] || fail "csv rows"
diff <(tail -n +2 "$work/out.csv" | cut -d, -f3) <(sed -E 's/.*"state":"([a-z]+)".*/\1/' "$work/out.jsonl") >/dev/null || fail "csv and jsonl states differ"

# --annotate writes a video.
timeout 60 "$raypoint" track "$clip" --annotate "$work/annotated.mp4" >/dev/null || fail "annotate exited $?"
[ -s "$work/annotated.mp4" ] || fail "no annotated video"

# Each estimator runs by name.
for name in ray iterative-ray iterative-ny-ray raster; do
  timeout 60 "$raypoint" track "$clip" --estimator "$name" | grep -q '"state":"tracking"' || fail "--estimator $name never tracked"
done

# Bad input: exit code, one line on stderr, and what it must name.
expect_timeout=30
: > "$work/empty.mp4"
echo "not a video at all" > "$work/text.mp4"
head -c 40000 "$clip" > "$work/truncated.mp4"
expect_error 1 "$work/missing.mp4: cannot open: No such file" track "$work/missing.mp4"
expect_error 1 "$work/empty.mp4: empty file" track "$work/empty.mp4"
expect_error 1 "$work/text.mp4: cannot decode as video" track "$work/text.mp4"
expect_error 1 "$work/truncated.mp4: cannot decode as video" track "$work/truncated.mp4"
expect_error 1 "$work: is a directory" track "$work"
expect_error 2 "--estimator nope: unknown estimator (allowed: ray|iterative-ray|iterative-ny-ray|raster)" track "$clip" --estimator nope
expect_error 2 "--set tracking.min_aera=0.1: unknown key (did you mean tracking.min_area?)" track "$clip" --set tracking.min_aera=0.1
expect_error 2 "--set tracking.min_area=2: value out of range (allowed: 0..1)" track "$clip" --set tracking.min_area=2
expect_error 2 "--set estimator.rays=many: not an integer (allowed: 3..256)" track "$clip" --set estimator.rays=many
expect_error 2 "--set tracking=1: expected section.key=value" track "$clip" --set tracking=1
expect_error 2 "--format xml: unknown format (allowed: jsonl|csv)" track "$clip" --format xml
expect_error 2 "missing INPUT" track
expect_error 2 "--bogus: unknown option" track "$clip" --bogus
expect_error 2 "frobnicate: unknown command" frobnicate
expect_error 2 "--fromat: unknown option (did you mean --format?)" track "$clip" --fromat csv
expect_error 2 "--fps 0: not a frame rate" track "$clip" --fps=0
expect_error 2 "--verbose: takes no value" track "$clip" --verbose=yes
# The output is checked before the first frame: nothing on stdout.
expect_error 1 "--annotate /nonexistent/x.mp4: cannot write: /nonexistent: No such file" track "$clip" --annotate /nonexistent/x.mp4
[ -s "$work/stdout.txt" ] && fail "--annotate to a missing folder printed frames first"
# --opt=value is --opt value.
timeout 60 "$raypoint" track "$clip" --format=csv --set=tracking.idle_seconds=5 > "$work/eq.csv" ||
  fail "--format=csv exited $?"
head -1 "$work/eq.csv" | grep -q '^frame,' || fail "--format=csv did not write CSV: $(head -1 "$work/eq.csv")"

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "raypoint track: all checks passed"
