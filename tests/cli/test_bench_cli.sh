#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint bench end to end: a rendered scene folder through the real command, every system's row
# checked for sane figures in each format, a clip without truth timed only, the rendered default
# scenes, and bad clips and options answered with one line on stderr and exit 1 (input) or 2
# (usage).
# usage: test_bench_cli.sh RAYPOINT RENDER_SCENE
set -u
raypoint=$1
render=$2
. "$(dirname "$0")/common.sh"

# 5 s: the target enters at 2.5 s and is scored from 3.5 s on (the 1 s grace, docs/scoring.md), 45 frames.
"$render" --preset ideal --seconds 5 --out "$work/ideal" >/dev/null || { echo "cannot render"; exit 1; }
systems="raypoint ray|raypoint iterative-ray|raypoint iterative-ny-ray|raypoint raster|camshift|kcf|csrt|mil"

# JSONL: one object a system, with timing and accuracy.
timeout 300 "$raypoint" bench "$work/ideal" --format jsonl > "$work/out.jsonl" 2> "$work/err.txt" || fail "bench exited $?"
[ ! -s "$work/err.txt" ] || fail "stderr not empty: $(head -1 "$work/err.txt")"
[ "$(wc -l < "$work/out.jsonl")" -eq 8 ] || fail "expected 8 rows, got $(wc -l < "$work/out.jsonl"): $(cat "$work/out.jsonl")"
IFS='|' read -ra names <<< "$systems"
for name in "${names[@]}"; do
  grep -q "^{\"clip\":\"ideal\",\"system\":\"$name\"," "$work/out.jsonl" || fail "no row for $name"
done
grep -q '"error"' "$work/out.jsonl" && fail "a system failed: $(grep '"error"' "$work/out.jsonl")"
# Sane values: timed frames are those after the peers' start; times positive, p95 >= median;
# tracked, errors and ratios in range; the reference (the default estimator) has ratio 1.
awk '
  function field(name,   m) { if (match($0, "\"" name "\":[^,}]+")) { m = substr($0, RSTART, RLENGTH); sub(/^[^:]+:/, "", m); return m } return "missing" }
  {
    sys = field("system"); cerr = field("cerr"); depth = field("depth_r")
    frames = field("frames") + 0; med = field("median_us") + 0; p95 = field("p95_us") + 0
    ratio = field("ratio") + 0; tracked = field("tracked")
    if (frames < 60 || frames > 150) { print "frames " frames " in " $0; bad = 1 }
    if (!(med > 0) || !(p95 >= med) || med > 1e6) { print "times in " $0; bad = 1 }
    if (!(ratio > 0)) { print "ratio in " $0; bad = 1 }
    if (tracked == "null" || tracked + 0 < 0 || tracked + 0 > 1) { print "tracked in " $0; bad = 1 }
    if (sys ~ /raypoint/ && tracked + 0 < 0.8) { print "raypoint lost the sphere: " $0; bad = 1 }
    if (sys ~ /raypoint/ && (cerr == "null" || cerr + 0 > 5)) { print "raypoint centroid error: " $0; bad = 1 }
    if (depth != "null" && (depth + 0 < -1 || depth + 0 > 1)) { print "depth r in " $0; bad = 1 }
    if (sys ~ /"raypoint raster"/ && ratio != 1) { print "reference ratio: " $0; bad = 1 }
  }
  END { exit bad }' "$work/out.jsonl" > "$work/insane.txt" || fail "insane values: $(cat "$work/insane.txt")"
# The ratio is the system's median over the reference's.
awk '
  function field(name,   m) { match($0, "\"" name "\":[^,}]+"); m = substr($0, RSTART, RLENGTH); sub(/^[^:]+:/, "", m); return m }
  /"raypoint raster"/ { ref = field("median_us") + 0 }
  { med[NR] = field("median_us") + 0; ratio[NR] = field("ratio") + 0 }
  END { for (i in med) { d = med[i] / ref - ratio[i]; if (d > 0.005 * ratio[i] + 0.002 || d < -0.005 * ratio[i] - 0.002) exit 1 } }' "$work/out.jsonl" || fail "ratios are not median / reference median"

# --estimator changes the reference; the table has a header and a row a system.
timeout 300 "$raypoint" bench "$work/ideal" --estimator ray --peers camshift --frames 130 > "$work/table.txt" || fail "table exited $?"
grep -qE '^ideal +raypoint ray +[0-9]+ +[0-9]+ +[0-9]+ +1\.00x ' "$work/table.txt" || fail "ray is not the reference: $(cat "$work/table.txt")"
[ "$(grep -c '^ideal ' "$work/table.txt")" -eq 5 ] || fail "--peers camshift: expected 5 rows: $(cat "$work/table.txt")"
grep -qE '^clip +system +frames +median us +p95 us' "$work/table.txt" || fail "table header: $(head -2 "$work/table.txt")"

# Markdown: a header, the rule and a row a system.
timeout 300 "$raypoint" bench "$work/ideal/video.mp4" --peers kcf --format markdown > "$work/table.md" || fail "markdown exited $?"
[ "$(grep -c '^| ideal | ' "$work/table.md")" -eq 5 ] || fail "markdown rows: $(cat "$work/table.md")"
head -2 "$work/table.md" | tail -1 | grep -q '^|---|' || fail "markdown rule: $(head -2 "$work/table.md")"

# A clip without truth beside it: timing only; two clips add the overall rows.
mkdir "$work/bare" && cp "$work/ideal/video.mp4" "$work/bare/clip.mp4"
timeout 300 "$raypoint" bench "$work/bare/clip.mp4" "$work/ideal" --peers mil --frames 130 --format jsonl > "$work/two.jsonl" || fail "two clips exited $?"
[ "$(grep -c '"clip":"clip"' "$work/two.jsonl")" -eq 5 ] || fail "clip rows: $(cat "$work/two.jsonl")"
grep '"clip":"clip"' "$work/two.jsonl" | grep -qv '"tracked":null' && fail "a clip without truth got accuracy"
grep '"clip":"clip"' "$work/two.jsonl" | grep -q '"median_us":null' && fail "a clip without truth got no timing"
[ "$(grep -c '"clip":"overall"' "$work/two.jsonl")" -eq 5 ] || fail "overall rows: $(cat "$work/two.jsonl")"

# Without CLIP: rendered scenes, in memory.
timeout 300 "$raypoint" bench --scenes nonconvex,ideal --frames 110 --peers none --format jsonl > "$work/rendered.jsonl" || fail "rendered exited $?"
[ "$(grep -c '"clip":"nonconvex"' "$work/rendered.jsonl")" -eq 4 ] || fail "rendered rows: $(cat "$work/rendered.jsonl")"
grep '"clip":"nonconvex"' "$work/rendered.jsonl" | grep -q '"tracked":null' && fail "rendered scene without accuracy"

# Bad input: exit code, one line on stderr, and what it must name.
mkdir "$work/text" "$work/empty" "$work/nomasks" "$work/badmasks" "$work/badtruth"
echo "not a video at all" > "$work/text/video.mp4"
for dir in nomasks badmasks badtruth; do cp "$work/ideal/video.mp4" "$work/ideal/truth.jsonl" "$work/$dir/"; done
head -c 100 /dev/zero > "$work/badmasks/masks.npz"
cp "$work/ideal/masks.npz" "$work/badtruth/"
sed -i '3s/.*/{"frame": 2, "t": "soon", "present": false}/' "$work/badtruth/truth.jsonl"
expect_error 1 "$work/missing.mp4: cannot open: No such file" bench "$work/missing.mp4"
expect_error 1 "$work/text/video.mp4: cannot decode as video" bench "$work/text"
expect_error 1 "$work/empty: is a directory without video.mp4" bench "$work/empty"
expect_error 1 "$work/nomasks/masks.npz: cannot open: No such file" bench "$work/nomasks" --peers none
expect_error 1 "$work/badmasks/masks.npz: no zip end record" bench "$work/badmasks" --peers none
expect_error 1 "$work/badtruth/truth.jsonl:3: t: not a number" bench "$work/badtruth" --peers none
expect_error 2 "--peers kcf,boosting: unknown peer 'boosting'" bench "$work/ideal" --peers kcf,boosting
expect_error 2 "--format xml: unknown format (allowed: table|markdown|jsonl)" bench --format xml
expect_error 2 "--frames 1: not a frame count" bench --frames 1
expect_error 2 "--scenes: unknown" bench --scenes nope
expect_error 2 "--bogus: unknown option" bench --bogus
expect_error 2 "--estimator nope: unknown estimator" bench --estimator nope

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "raypoint bench: all checks passed"
