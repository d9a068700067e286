#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint run without its camera: it starts anyway, says "waiting for a camera" (log, ctl status,
# ctl status --json) instead of exiting into a restart loop, and answers pause, resume and toggle.
# The camera's appearance, and pause closing it, need a device: the VM tests have one.
#   test_camera_wait.sh RAYPOINT
set -u
raypoint=$1
source "$(dirname "$0")/common.sh"
socket="$work/raypoint.sock"
missing=/dev/raypoint-test-no-such-camera

"$raypoint" run --camera "$missing" --sink null --control "$socket" --duration 20 \
  2> "$work/run.log" &
daemon=$!
trap 'kill "$daemon" 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 100); do [ -S "$socket" ] && break; sleep 0.1; done
[ -S "$socket" ] || fail "no control socket: $(cat "$work/run.log")"

status=$("$raypoint" ctl status --control "$socket") || fail "ctl status exited $?"
grep -q "^source: waiting for a camera (.*$missing" <<<"$status" || fail "status: $status"
json=$("$raypoint" ctl status --json --control "$socket") || fail "ctl status --json exited $?"
python3 -c 'import json, sys; d = json.loads(sys.argv[1]); assert d["paused"] is False, d; assert d["frames"] == 0, d; assert d["source"].startswith("waiting for a camera"), d' "$json" ||
  fail "ctl status --json: $json"
[ "$("$raypoint" ctl toggle --control "$socket")" = paused ] || fail "toggle did not pause"
"$raypoint" ctl status --json --control "$socket" | grep -q '"paused":true' || fail "not paused"
[ "$("$raypoint" ctl toggle --control "$socket")" = resumed ] || fail "toggle did not resume"
[ "$("$raypoint" ctl pause --control "$socket")" = paused ] || fail "pause"
[ "$("$raypoint" ctl resume --control "$socket")" = resumed ] || fail "resume"
kill -0 "$daemon" 2>/dev/null || fail "the daemon exited without a camera: $(cat "$work/run.log")"
kill -TERM "$daemon"
wait "$daemon"
code=$?
[ "$code" -eq 0 ] || fail "SIGTERM while waiting: exit $code"
grep -q "waiting for a camera: .*$missing" "$work/run.log" || fail "log: $(cat "$work/run.log")"
expect_error 2 "--json: only for status" ctl pause --json --control "$socket"

[ "$failures" -eq 0 ] || { echo "$failures failures"; exit 1; }
echo "raypoint run without a camera: all checks passed"
