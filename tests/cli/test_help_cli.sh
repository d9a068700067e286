#!/bin/bash
# SPDX-License-Identifier: MIT
# The command line's conventions through the service executable: --help on every command exits
# 0, --version, suggestions for misspelt options and commands, one exit-code rule (2 usage,
# 1 input or settings), and raypoint(1) naming every option the CLI accepts.
#   test_help_cli.sh RAYPOINT MAN_PAGE
set -u
raypoint=$1
man_page=$2
source "$(dirname "$0")/common.sh"

"$raypoint" --help > "$work/usage.txt" || fail "raypoint --help exited $?"
commands=$(sed -n 's/^  \([a-z][a-z-]*\).*/\1/p' "$work/usage.txt")
[ "$(wc -w <<<"$commands")" -ge 9 ] || fail "raypoint --help lists too few commands: $commands"
for command in $commands; do
  for flag in --help -h; do
    "$raypoint" "$command" $flag > "$work/help.txt" 2> "$work/help.err" ||
      fail "raypoint $command $flag exited $?"
    [ -s "$work/help.err" ] && fail "raypoint $command $flag wrote on stderr: $(cat "$work/help.err")"
    grep -q "^usage: raypoint $command" "$work/help.txt" || fail "raypoint $command $flag: no usage line"
  done
  # Every option the command accepts, and every command, in the man page (roff writes - as \-).
  grep -qF -- "$(sed 's/-/\\-/g' <<<"$command")" "$man_page" || fail "raypoint(1) lacks the command $command"
  for option in $(sed -n 's/^ *\(--[a-z][a-z-]*\).*/\1/p' "$work/help.txt" | sort -u); do
    grep -qF -- "$(sed 's/-/\\-/g' <<<"$option")" "$man_page" ||
      fail "raypoint(1) lacks $option (an option of raypoint $command)"
  done
done

"$raypoint" --version > "$work/version.txt" || fail "raypoint --version exited $?"
grep -qE '^raypoint [0-9]+\.[0-9]+\.[0-9]+' "$work/version.txt" || fail "--version: $(cat "$work/version.txt")"

expect_error 2 "--camara: unknown option (did you mean --camera?)" run --camara /dev/video0
expect_error 2 "--xyzzy-plugh: unknown option; see raypoint run --help" run --xyzzy-plugh
expect_error 2 "unknown command (did you mean doctor?)" docter
expect_error 2 "--set estimator.rays=1000: value out of range" print-config --set estimator.rays=1000
expect_error 2 "--estimator foo: unknown estimator" print-config --estimator=foo
expect_error 1 "/nonexistent/raypoint.ini: " print-config --config /nonexistent/raypoint.ini
"$raypoint" > /dev/null 2>&1
[ $? -eq 2 ] || fail "raypoint without a command: not exit 2"

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "raypoint help, version, options and raypoint(1): all checks passed"
