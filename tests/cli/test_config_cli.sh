#!/bin/bash
# SPDX-License-Identifier: MIT
# check-config, print-config and --config through the real executable: exact messages and exit
# codes, the XDG search path (in temporary directories), the command line over the file.
# usage: test_config_cli.sh RAYPOINT
set -u
raypoint=$1
. "$(dirname "$0")/common.sh"
# Runs the command; leaves its exit code in $rc, stdout in $work/out, stderr in $work/err.
run() { timeout 30 "$@" > "$work/out" 2> "$work/err"; rc=$?; }
# The search path only ever sees this test's directories.
export HOME="$work/home" XDG_CONFIG_HOME="$work/user" XDG_CONFIG_DIRS="$work/system"

printf '[estimator]\nrays = 2\nrayz = 8\n[trackin]\n' > "$work/bad.ini"
expected_errors="$work/bad.ini:2: [estimator] rays: value out of range (allowed: 3..256)
$work/bad.ini:3: [estimator] rayz: unknown key (did you mean rays?)
$work/bad.ini:4: [trackin]: unknown section (did you mean [tracking]?)"

# check-config FILE: every error, one a line, on stderr; exit 1.
run "$raypoint" check-config "$work/bad.ini"
[ "$rc" -eq 1 ] || fail "check-config bad.ini exited $rc"
[ "$(cat "$work/err")" = "$expected_errors" ] || fail "check-config errors: $(cat "$work/err")"
[ ! -s "$work/out" ] || fail "check-config bad.ini wrote to stdout: $(cat "$work/out")"

# Hostile input: control characters come out escaped (a raw ESC ] ... BEL would retitle the
# terminal), garbage gets no suggestion, an enum's value is read whatever its case, a wrong one
# gets the closest, and a cross-key error has its line.
printf '[tracking]\n\033]0;pwned\007 = 1\n[pointer]\nmode = Absolute\n[estimator]\nmethod = iterativ-ray\n[click]\npress_rise = 0.01\nrelease_rise = 0.5\n' > "$work/hostile.ini"
run "$raypoint" check-config "$work/hostile.ini"
[ "$rc" -eq 1 ] || fail "check-config hostile.ini exited $rc"
grep -q "$(printf '\033')" "$work/err" && fail "a raw ESC reached the terminal: $(cat -v "$work/err")"
grep -qF ':2: [tracking] \x1b]0;pwned\x07: unknown key (raypoint print-config lists every key)' "$work/err" ||
  fail "the garbage key is not escaped, or got a suggestion: $(cat -v "$work/err")"
grep -q "mode" "$work/err" && fail "mode = Absolute was refused: $(cat "$work/err")"
grep -qF ':6: [estimator] method: unknown value, did you mean iterative-ray?' "$work/err" ||
  fail "no suggestion for a misspelt value: $(cat "$work/err")"
printf '[click]\npress_rise = 0.01\nrelease_rise = 0.5\n' > "$work/crossed.ini"
run "$raypoint" check-config "$work/crossed.ini"
grep -qF "$work/crossed.ini:3: click.release_rise must be below click.press_rise" "$work/err" ||
  fail "the cross-key error has no line: $(cat "$work/err")"

printf '[estimator]\nrays = 8\n' > "$work/good.ini"
run "$raypoint" check-config "$work/good.ini"
[ "$rc" -eq 0 ] && [ "$(cat "$work/out")" = "$work/good.ini: ok" ] || fail "check-config good.ini: $rc $(cat "$work/out" "$work/err")"

run "$raypoint" check-config "$work/missing.ini"
[ "$rc" -eq 1 ] && [ "$(cat "$work/err")" = "$work/missing.ini: cannot open: No such file or directory" ] || fail "check-config missing: $rc $(cat "$work/err")"

# An unreadable file names the reason. root reads anything, so as root check as nobody.
printf '[estimator]\n' > "$work/locked.ini"
chmod 000 "$work/locked.ini"
chmod 755 "$work"
as_user=()
if [ "$(id -u)" -eq 0 ]; then as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups); fi
# (skipped when nobody cannot reach the executable, e.g. a build under a private home)
if [ "$(id -u)" -ne 0 ] || { command -v setpriv > /dev/null && "${as_user[@]}" test -x "$raypoint"; }; then
    run "${as_user[@]}" "$raypoint" check-config "$work/locked.ini"
    [ "$rc" -eq 1 ] && [ "$(cat "$work/err")" = "$work/locked.ini: cannot open: Permission denied" ] || fail "check-config locked: $rc $(cat "$work/err")"
fi

# check-config without FILE: the file raypoint run would read, and it says which.
run "$raypoint" check-config
[ "$rc" -eq 0 ] || fail "check-config without a file exited $rc"
[ "$(cat "$work/out")" = "no configuration file (looked for $work/user/raypoint/raypoint.ini, $work/system/raypoint/raypoint.ini): raypoint run uses the defaults" ] || fail "no file: $(cat "$work/out")"
mkdir -p "$work/system/raypoint" "$work/user/raypoint"
cp "$work/good.ini" "$work/system/raypoint/raypoint.ini"
run "$raypoint" check-config
[ "$rc" -eq 0 ] && [ "$(cat "$work/out")" = "checking $work/system/raypoint/raypoint.ini, the file raypoint run reads
$work/system/raypoint/raypoint.ini: ok" ] || fail "system file: $rc $(cat "$work/out")"
cp "$work/bad.ini" "$work/user/raypoint/raypoint.ini"
run "$raypoint" check-config
[ "$rc" -eq 1 ] || fail "bad user file: exit $rc"
[ "$(head -1 "$work/out")" = "checking $work/user/raypoint/raypoint.ini, the file raypoint run reads" ] || fail "user file first: $(cat "$work/out")"
[ "$(cat "$work/err")" = "${expected_errors//$work\/bad.ini/$work/user/raypoint/raypoint.ini}" ] || fail "user file errors: $(cat "$work/err")"

# print-config reads the file raypoint run would; --defaults reads none.
printf '[estimator]\nrays = 12\n' > "$work/user/raypoint/raypoint.ini"
run "$raypoint" print-config
[ "$rc" -eq 0 ] && grep -qx 'rays = 12' "$work/out" || fail "print-config did not read the user file"
[ "$(head -1 "$work/out")" = "# read from $work/user/raypoint/raypoint.ini" ] || fail "print-config header: $(head -1 "$work/out")"
run "$raypoint" print-config --defaults
[ "$rc" -eq 0 ] && grep -qx 'rays = 16' "$work/out" || fail "print-config --defaults read a file"

# The command line wins over the file; the output is a valid file that reads back the same.
printf '[general]\npreset = paper\n[estimator]\nrays = 8\nmethod = ray\n' > "$work/paper.ini"
run "$raypoint" print-config --config "$work/paper.ini" --set estimator.rays=9
[ "$rc" -eq 0 ] || fail "print-config --config exited $rc: $(cat "$work/err")"
grep -qx 'rays = 9' "$work/out" || fail "--set did not win over the file"
grep -qx 'method = ray' "$work/out" || fail "the file's method was lost"
grep -qx 'edge_threshold = 128' "$work/out" || fail "the file's preset was not applied"
cp "$work/out" "$work/printed.ini"
run "$raypoint" print-config --config "$work/printed.ini"
diff <(tail -n +2 "$work/printed.ini") <(tail -n +2 "$work/out") > /dev/null || fail "print-config output does not read back the same"

# The offline commands take --config and answer a bad file before anything else.
for command in "track clip.mp4" "demo" "compare-estimators"; do
    run "$raypoint" $command --config "$work/bad.ini"
    [ "$rc" -eq 1 ] || fail "$command --config bad.ini exited $rc"
    [ "$(cat "$work/err")" = "$(sed "s|^|raypoint ${command%% *}: |" <<< "$expected_errors")" ] || fail "$command errors: $(cat "$work/err")"
done

# Usage errors exit 2.
run "$raypoint" check-config a.ini b.ini
[ "$rc" -eq 2 ] || fail "check-config with two files exited $rc"
run "$raypoint" print-config --defaults --config "$work/good.ini"
[ "$rc" -eq 2 ] || fail "print-config --defaults --config exited $rc"
run "$raypoint" track clip.mp4 --config
[ "$rc" -eq 2 ] || fail "--config without a value exited $rc"

[ "$failures" -eq 0 ] && echo "all config CLI checks passed"
exit $((failures > 0))
