#!/bin/bash
# SPDX-License-Identifier: MIT
# Logging under systemd: with $JOURNAL_STREAM naming stderr (as systemd sets it for a service
# whose stderr is the journal), a failed start is logged with the err priority prefix "<3>"
# that journald reads; with stderr on a pipe, or $JOURNAL_STREAM naming another file, no "<N>".
#   test_journal_priority.sh RAYPOINT
set -u
raypoint=$1
source "$(dirname "$0")/common.sh"

# A file stands for the journal's stream socket: what matters is that its device and inode are
# those of stderr.
: > "$work/journal"
stream=$(stat -c '%d:%i' "$work/journal")
JOURNAL_STREAM=$stream "$raypoint" run --config "$work/missing.ini" --no-control --sink null \
  2>> "$work/journal"
[ $? -eq 1 ] || fail "run with a missing --config did not exit 1"
grep -q "^<3>raypoint run: .*missing.ini" "$work/journal" ||
  fail "the failed start is not at err (<3>) with its reason: $(cat "$work/journal")"

# A pipe, with and without a $JOURNAL_STREAM inherited from a service: plain text.
for value in "" "$stream"; do
  out=$(JOURNAL_STREAM=$value "$raypoint" run --config "$work/missing.ini" --no-control \
    --sink null 2>&1 | cat)
  grep -q "missing.ini" <<<"$out" || fail "no reason on the pipe: $out"
  grep -q "<[0-9]>" <<<"$out" && fail "a priority prefix on a pipe (JOURNAL_STREAM='$value'): $out"
done

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "journal priorities: all checks passed"
