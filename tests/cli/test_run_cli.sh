#!/bin/bash
# SPDX-License-Identifier: MIT
# raypoint run end to end on rendered clips, with the event sink that records to a file: the
# push gesture clicks exactly twice, a clip without one never clicks; the control socket, SIGHUP
# reload (a broken file keeps the running configuration), SIGTERM; and bad input.
# usage: test_run_cli.sh RAYPOINT RENDER_SCENE
set -u
raypoint=$1
render=$2
. "$(dirname "$0")/common.sh"
daemon_pid=""
trap '[ -n "$daemon_pid" ] && kill -9 "$daemon_pid" 2>/dev/null; rm -rf "$work"' EXIT
export XDG_RUNTIME_DIR="$work/runtime" XDG_CONFIG_HOME="$work/config" XDG_CONFIG_DIRS="$work/none"
mkdir -p "$XDG_RUNTIME_DIR"

"$render" --preset push --out "$work/push" --no-masks >/dev/null || { echo "cannot render"; exit 1; }
"$render" --preset nonconvex --out "$work/nonconvex" --no-masks >/dev/null || exit 1

# Clicks from a push gesture, none without one.
timeout 120 "$raypoint" run --input "$work/push/video.mp4" --unpaced --no-control \
  --sink "file:$work/push.events" 2>"$work/push.log" || fail "run on push exited $?"
presses=$(grep -c 'EV_KEY BTN_LEFT 1$' "$work/push.events")
releases=$(grep -c 'EV_KEY BTN_LEFT 0$' "$work/push.events")
[ "$presses" -eq 2 ] && [ "$releases" -eq 2 ] || fail "push: $presses presses, $releases releases (expected 2, 2)"
# The pushes start at 5.0 s and 6.6 s: each press within 0.5 s of its push.
first=$(grep 'EV_KEY BTN_LEFT 1$' "$work/push.events" | head -1 | cut -d' ' -f1)
second=$(grep 'EV_KEY BTN_LEFT 1$' "$work/push.events" | sed -n 2p | cut -d' ' -f1)
[ "${first:-0}" -ge 5000000 ] && [ "${first:-0}" -le 5500000 ] || fail "first press at ${first:-none} us"
[ "${second:-0}" -ge 6600000 ] && [ "${second:-0}" -le 7100000 ] || fail "second press at ${second:-none} us"
grep -q 'EV_REL REL_X' "$work/push.events" || fail "push: no motion"
timeout 120 "$raypoint" run --input "$work/nonconvex/video.mp4" --unpaced --no-control \
  --sink "file:$work/nonconvex.events" 2>/dev/null || fail "run on nonconvex exited $?"
[ "$(grep -c 'EV_KEY' "$work/nonconvex.events")" -eq 0 ] || fail "nonconvex clicked"
grep -q 'EV_REL REL_X' "$work/nonconvex.events" || fail "nonconvex: no motion"

# The live loop: control socket, reload, stop. The clip loops (--realtime) for far longer than
# the checks take, so SIGTERM, not the clip's end, stops it on a slow or loaded machine too.
mkdir -p "$XDG_CONFIG_HOME/raypoint"
"$raypoint" run --input "$work/push/video.mp4" --realtime --duration 240 \
  --sink "file:$work/live.events" 2>"$work/live.log" &
daemon_pid=$!
for _ in $(seq 50); do [ -S "$XDG_RUNTIME_DIR/raypoint.sock" ] && break; sleep 0.1; done
sleep 1
# No network socket anywhere: every socket the running daemon holds is a unix one (the control
# socket; sd_notify's too under systemd), none in the kernel's TCP, UDP, raw or packet tables.
# The control socket's file is the user's alone.
[ "$(stat -c %a "$XDG_RUNTIME_DIR/raypoint.sock")" = 600 ] ||
  fail "control socket mode $(stat -c %a "$XDG_RUNTIME_DIR/raypoint.sock"), not 600"
inodes=$(for fd in /proc/$daemon_pid/fd/*; do readlink "$fd"; done |
  sed -n 's/^socket:\[\([0-9]*\)\]$/\1/p' | tr '\n' ' ')
[ -n "$inodes" ] || fail "no socket found in /proc/$daemon_pid/fd (the control socket?)"
net=/proc/$daemon_pid/net
# The inode column: 10th in the TCP, UDP and raw tables, 9th in packet's, 7th in unix's.
in_table() {  # COLUMN FILE...: the inodes of $inodes in the files' COLUMN (missing files skipped)
  local column=$1 file files=()
  shift
  for file in "$@"; do [ -r "$file" ] && files+=("$file"); done
  [ ${#files[@]} -gt 0 ] || return 0
  awk -v list="$inodes" -v column="$column" 'BEGIN {split(list, wanted, " ")
      for (i in wanted) want[wanted[i]] = 1}
    FNR > 1 && ($column in want) {print $column}' "${files[@]}"
}
network=$(in_table 10 $net/tcp $net/tcp6 $net/udp $net/udp6 $net/udplite $net/udplite6 $net/raw $net/raw6)
network+=$(in_table 9 $net/packet)
[ -z "$network" ] || fail "network sockets in the daemon: inodes $network"
unix_count=$(in_table 7 $net/unix | sort -u | wc -l)
[ "$unix_count" -eq "$(wc -w <<<"$inodes")" ] ||
  fail "sockets $inodes: only $unix_count of them unix sockets"
"$raypoint" ctl status > "$work/status.txt" || fail "ctl status exited $?"
grep -q '^state: ' "$work/status.txt" || fail "status: $(cat "$work/status.txt")"
grep -q '^paused: no' "$work/status.txt" || fail "status before pause: $(cat "$work/status.txt")"
for field in '^fps: ' '^cpu: ' '^run cpu: [0-9.]*% of one core' '^peak rss: [0-9.]* MiB' \
             '^latency ready to write: median [0-9]* us, p99 [0-9]* us'; do
  grep -q "$field" "$work/status.txt" || fail "status has no '$field': $(cat "$work/status.txt")"
done
"$raypoint" doctor > "$work/doctor.txt"
grep -q '^ok   service  raypoint run answers on ' "$work/doctor.txt" || fail "doctor: $(cat "$work/doctor.txt")"
grep -q '^ok   config ' "$work/doctor.txt" || fail "doctor config: $(cat "$work/doctor.txt")"
# The service never needs root, and doctor says so to root.
if [ "$(id -u)" -eq 0 ]; then
  grep -q '^note user     running as root: raypoint never needs root' "$work/doctor.txt" ||
    fail "doctor as root: $(cat "$work/doctor.txt")"
else
  grep -q '^ok   user     runs as uid [0-9]*, not root' "$work/doctor.txt" ||
    fail "doctor as a user: $(cat "$work/doctor.txt")"
fi
[ "$("$raypoint" ctl pause)" = "paused" ] || fail "ctl pause"
"$raypoint" ctl status | grep -q '^paused: yes' || fail "status after pause"
[ "$("$raypoint" ctl resume)" = "resumed" ] || fail "ctl resume"
echo "[tracking]
min_area = 7" > "$XDG_CONFIG_HOME/raypoint/raypoint.ini"
"$raypoint" doctor > "$work/doctor.txt" && fail "doctor passed with a broken file"
grep -q '^FAIL config .*raypoint.ini has 1 error(s), the first: .*raypoint.ini:2: \[tracking\] min_area' "$work/doctor.txt" ||
  fail "doctor on a broken file: $(cat "$work/doctor.txt")"
grep -q 'fix: raypoint check-config lists them all' "$work/doctor.txt" || fail "doctor gave no fix"
kill -HUP "$daemon_pid"
sleep 0.5
kill -0 "$daemon_pid" 2>/dev/null || fail "the daemon died on a reload with a broken file"
grep -q "reload failed, keeping the running configuration" "$work/live.log" || fail "no reload error: $(cat "$work/live.log")"
grep -q "raypoint.ini:2: \[tracking\] min_area: value out of range" "$work/live.log" || fail "reload error without file:line"
rm "$XDG_CONFIG_HOME/raypoint/raypoint.ini"
kill -HUP "$daemon_pid"
sleep 0.3
grep -q "configuration reloaded" "$work/live.log" || fail "no reload"
kill -TERM "$daemon_pid"
wait "$daemon_pid"
code=$?
daemon_pid=""
[ "$code" -eq 0 ] || fail "SIGTERM: exit $code"
[ ! -e "$XDG_RUNTIME_DIR/raypoint.sock" ] || fail "socket left behind"
grep -q "stopping on Terminated" "$work/live.log" || fail "no stop message"

# --realtime: the clip decoded first, replayed as a YUYV camera through the control socket's
# loop; looped to fill --duration; the cost summary at exit and in ctl status.
"$raypoint" run --input "$work/nonconvex/video.mp4" --realtime --duration 3 \
  --sink "file:$work/realtime.events" 2>"$work/realtime.log" &
daemon_pid=$!
for _ in $(seq 50); do [ -S "$XDG_RUNTIME_DIR/raypoint.sock" ] && break; sleep 0.1; done
sleep 1
"$raypoint" ctl status > "$work/status.txt" || fail "ctl status (realtime) exited $?"
grep -q '^source: .*replayed in real time as YUYV 640x480' "$work/status.txt" ||
  fail "realtime status: $(cat "$work/status.txt")"
grep -q '^latency handed to write: median [0-9]* us' "$work/status.txt" ||
  fail "realtime status: $(cat "$work/status.txt")"
wait "$daemon_pid"
code=$?
daemon_pid=""
[ "$code" -eq 0 ] || fail "--realtime --duration 3: exit $code"
grep -q 'stopping: --duration reached' "$work/realtime.log" || fail "realtime: $(cat "$work/realtime.log")"
grep -q 'cost of this run:' "$work/realtime.log" || fail "no cost summary: $(cat "$work/realtime.log")"
grep -q 'run cpu: [0-9.]*% of one core (user' "$work/realtime.log" || fail "no run cpu in the summary"
grep -q 'latency ready to write: median [0-9]* us, p99' "$work/realtime.log" || fail "no latency in the summary"
grep -q 'EV_REL REL_X' "$work/realtime.events" || fail "realtime: no motion"
# --realtime-format mjpeg: the same clip as an MJPEG camera's frames, decoded when due at the
# camera path's size (320x240 by default: 4/8 of 640x480); it tracks and moves the pointer too.
"$raypoint" run --input "$work/nonconvex/video.mp4" --realtime --realtime-format mjpeg \
  --duration 3 --sink "file:$work/mjpeg.events" --no-control 2>"$work/mjpeg.log" ||
  fail "--realtime-format mjpeg: exit $? ($(cat "$work/mjpeg.log"))"
grep -q 'replayed in real time as MJPEG 640x480, decoded at 4/8 scale' "$work/mjpeg.log" ||
  fail "mjpeg: $(cat "$work/mjpeg.log")"
grep -q 'run cpu: [0-9.]*% of one core (user' "$work/mjpeg.log" || fail "mjpeg: no run cpu"
grep -q ' 0 dropped)' "$work/mjpeg.log" || fail "mjpeg: frames dropped: $(cat "$work/mjpeg.log")"
grep -q 'EV_REL REL_X' "$work/mjpeg.events" || fail "mjpeg: no motion"
"$raypoint" run --input "$work/nonconvex/video.mp4" --realtime-format mjpeg --sink null \
  --no-control 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "realtime-format is the replayed camera's format: it needs --realtime" \
  "$work/err.txt" || fail "--realtime-format alone: $(cat "$work/err.txt")"
"$raypoint" run --input "$work/nonconvex/video.mp4" --realtime --realtime-format nv12 \
  --sink null --no-control 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "realtime-format nv12: unknown (allowed: yuyv, mjpeg)" "$work/err.txt" ||
  fail "--realtime-format nv12: $(cat "$work/err.txt")"
"$raypoint" run --realtime --sink null --no-control 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "needs --input" "$work/err.txt" || fail "--realtime alone: $(cat "$work/err.txt")"
"$raypoint" run --input "$work/push/video.mp4" --duration 0 --sink null 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "duration 0: needs seconds > 0" "$work/err.txt" || fail "--duration 0: $(cat "$work/err.txt")"

# doctor without a daemon: the service check fails with its fix.
"$raypoint" doctor > "$work/doctor.txt" && fail "doctor passed without a daemon"
grep -q '^FAIL service  raypoint run is not running' "$work/doctor.txt" || fail "doctor: $(cat "$work/doctor.txt")"
grep -q 'fix: systemctl --user enable --now raypoint' "$work/doctor.txt" || fail "doctor: no service fix"

# Bad input: a one-line reason and a non-zero exit.
"$raypoint" ctl status >/dev/null 2>"$work/err.txt" && fail "ctl without a daemon succeeded"
grep -q "is the daemon running?" "$work/err.txt" || fail "ctl error: $(cat "$work/err.txt")"
"$raypoint" run --input "$work/missing.mp4" --no-control 2>"$work/err.txt"
[ $? -eq 1 ] && grep -q "missing.mp4: cannot open" "$work/err.txt" || fail "missing input: $(cat "$work/err.txt")"
"$raypoint" run --input "$work/push/video.mp4" --sink bogus 2>"$work/err.txt"
[ $? -eq 2 ] && grep -q "unknown sink" "$work/err.txt" || fail "bad sink: $(cat "$work/err.txt")"
# A missing camera is waited for, not an error (test_camera_wait.sh has more).
"$raypoint" run --camera "$work/video9" --sink null --no-control --duration 1 2>"$work/err.txt"
[ $? -eq 0 ] && grep -q "waiting for a camera: .*video9" "$work/err.txt" ||
  fail "missing camera: $(cat "$work/err.txt")"

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "raypoint run: all checks passed"
