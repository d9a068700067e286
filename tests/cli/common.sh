# SPDX-License-Identifier: MIT
# Sourced by the CLI tests (after `set -u` and setting $raypoint): a scratch directory $work,
# removed at exit (a script that needs more at exit sets its own trap after sourcing), fail() to
# count a failed check, and expect_error.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect_error EXIT TEXT ARGS...: `$raypoint ARGS...` exits EXIT and prints exactly one line on
# stderr, containing TEXT (the project's rule for bad input: one line naming the input and the
# reason). $expect_timeout seconds (default 60) bound each run.
expect_error() {
  local code=$1 find=$2
  shift 2
  timeout "${expect_timeout:-60}" "$raypoint" "$@" > "$work/stdout.txt" 2> "$work/stderr.txt"
  local got=$?
  [ "$got" -eq "$code" ] || fail "'$*' exited $got, expected $code"
  [ "$(wc -l < "$work/stderr.txt")" -eq 1 ] || fail "'$*' printed $(wc -l < "$work/stderr.txt") lines on stderr: $(cat "$work/stderr.txt")"
  grep -qF -- "$find" "$work/stderr.txt" || fail "'$*' error lacks '$find': $(cat "$work/stderr.txt")"
}
