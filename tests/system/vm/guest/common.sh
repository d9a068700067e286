# SPDX-License-Identifier: MIT
# Helpers for the scenarios (sourced by run.sh, in the VM): devices, the processes under test,
# checks and transcript sums. A transcript line is "SECONDS TYPE CODE VALUE" (evdev_recorder);
# clip times are transcript times minus the writer's origin (loopback_writer).
raypoint="$raypoint_binary"
tools="$tools_dir"
clips="$vm_dir/clips"
camera=/dev/video0
failures=0
first_failure=""

ok() { echo "ok   $*"; }
bad() {
  echo "FAIL $*"
  failures=$((failures + 1))
  [ -n "$first_failure" ] || first_failure="$*"
}
# check DESCRIPTION COMMAND...: runs the command, ok or FAIL by its status.
check() {
  local what=$1
  shift
  if "$@"; then ok "$what"; else bad "$what"; fi
}

load_modules() {
  modprobe -a evdev uinput || bad "modprobe evdev uinput"
  load_loopback
}
# Three nodes, /dev/video0-2, each a capture device from its writer's first frame. One node a
# writer: once a writer has closed a node, the next one cannot set its format there (EINVAL).
load_loopback() {
  modprobe v4l2loopback devices=3 video_nr=0,1,2 exclusive_caps=1,1,1 \
    card_label="raypoint loopback 0,raypoint loopback 1,raypoint loopback 2" ||
    bad "modprobe v4l2loopback"
}

# wait_for FILE PATTERN SECONDS: until the file has a line matching the extended regex.
wait_for() {
  local deadline=$((SECONDS + $3))
  while [ "$SECONDS" -le "$deadline" ]; do
    grep -qE "$2" "$1" 2>/dev/null && return 0
    sleep 0.1
  done
  return 1
}

# start_writer CLIP LOG [play options]: plays the clip (CLIP.yuyv, or CLIP as named, e.g.
# rightdown.mjpg) into $camera (with --wait:
# its first frame until go) and returns after the first frame. Sets writer_pid, and origin
# (clip time 0, CLOCK_MONOTONIC seconds) unless it waits.
start_writer() {
  local clip=$1
  writer_log="$work/$2"
  shift 2
  local file="$clips/$clip"
  [ -e "$file" ] || file="$file.yuyv"
  "$tools/raypoint-loopback-writer" play "$file" "$camera" "$@" >"$writer_log" 2>&1 &
  writer_pid=$!
  wait_for "$writer_log" '^first frame' 30 || bad "writer: no first frame ($(cat "$writer_log"))"
  case " $* " in
    *" --wait "*) ;;
    *) go ;;
  esac
}
# go: the waiting writer starts the clip; sets origin.
go() {
  kill -USR1 "$writer_pid"
  wait_for "$writer_log" '^origin ' 10 || bad "writer: no origin ($(cat "$writer_log"))"
  origin=$(awk '$1 == "origin" {print $2; exit}' "$writer_log")
}

# start_recorder LOG: reads the virtual pointer's events once it appears. Sets recorder_pid.
start_recorder() {
  "$tools/raypoint-evdev-recorder" --wait 60 >"$work/$1" 2>&1 &
  recorder_pid=$!
}

# start_listener: a NOTIFY_SOCKET for the daemon (notify_listener). Sets listener_pid.
start_listener() {
  notify_socket="$XDG_RUNTIME_DIR/$1.socket"
  notify_log="$work/$1"
  "$tools/raypoint-notify-listener" "$notify_socket" >"$notify_log" 2>&1 &
  listener_pid=$!
  wait_for "$notify_log" '^listening' 10 || bad "notify listener did not start"
}

# write_config FILE MODE [DEVICE]: a real configuration file; the defaults but for these keys
# (DEVICE: $camera). Mirror off: the clip's right is the cursor's right.
write_config() {
  cat >"$1" <<INI
# raypoint in the VM: a loopback camera, $2 motion.
[pointer]
mode = $2
mirror = false

[camera]
device = ${3:-$camera}
INI
}

# start_daemon CONFIG NAME [run options]: raypoint run, its log in daemon-NAME.log, with a
# notify listener (notify-NAME.txt) as NOTIFY_SOCKET. Sets daemon_pid.
start_daemon() {
  local config=$1 name=$2
  shift 2
  start_listener "notify-$name.txt"
  daemon_log="$work/daemon-$name.log"
  NOTIFY_SOCKET=$notify_socket "$raypoint" run --config "$config" "$@" >"$daemon_log" 2>&1 &
  daemon_pid=$!
}
# wait_ready: until the daemon sent READY=1 (a cold start in the VM takes up to half a minute:
# 250 shared libraries through 9p under TCG).
wait_ready() {
  local deadline=$((SECONDS + 120))
  while [ "$SECONDS" -le "$deadline" ] && kill -0 "$daemon_pid" 2>/dev/null; do
    grep -q ' READY=1$' "$notify_log" && return 0
    sleep 0.1
  done
  grep -q ' READY=1$' "$notify_log" && return 0
  bad "no READY=1 from the daemon ($(tail -3 "$daemon_log"))"
  return 1
}

# stop PID...: SIGTERM and wait (a process that has exited already is fine).
stop() {
  local pid
  for pid in "$@"; do
    [ -n "$pid" ] || continue
    kill -TERM "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
}
stop_all() {
  local pids
  pids=$(jobs -p)
  [ -n "$pids" ] && kill -TERM $pids 2>/dev/null
  [ -n "$pids" ] && wait $pids 2>/dev/null
}

# Clip time is (event time - origin) x speed: the writer's --speed of the clip last played.
speed=1
# sum TRANSCRIPT CODE FROM TO: the sum of CODE's values from clip time FROM to TO (s).
sum() {
  awk -v o="$origin" -v x="$speed" -v c="$2" -v a="$3" -v b="$4" \
    '$3 == c { t = ($1 - o) * x; if (t >= a && t < b) s += $4 } END { print s + 0 }' "$1"
}
# value_at TRANSCRIPT CODE TIME: CODE's last value at or before clip time TIME (empty: none).
value_at() {
  awk -v o="$origin" -v x="$speed" -v c="$2" -v a="$3" \
    '$3 == c && ($1 - o) * x <= a { v = $4 } END { print v }' "$1"
}
# count TRANSCRIPT REGEX: lines matching.
count() { grep -cE "$2" "$1"; }
# ge A B / le A B: integer comparisons for check.
ge() { [ "${1:-0}" -ge "${2:-0}" ]; }
le() { [ "${1:-0}" -le "${2:-0}" ]; }
abs() { local v=${1:-0}; echo "${v#-}"; }
eq() { [ "${1:-x}" = "${2:-y}" ]; }

# run_clip CLIP CONFIG NAME: the whole clip through a fresh daemon, its events in
# events-NAME.txt; the daemon is stopped after the clip.
run_clip() {
  start_writer "$1" "writer-$3.log" --wait
  start_recorder "events-$3.txt"
  start_daemon "$2" "$3"
  wait_ready
  go
  wait "$writer_pid"
  sleep 0.5
  stop "$daemon_pid" "$recorder_pid" "$listener_pid"
}

# button_times TRANSCRIPT VALUE: clip times of BTN_LEFT VALUE (1 press, 0 release), one a line.
button_times() {
  awk -v o="$origin" -v v="$2" '$3 == "BTN_LEFT" && $4 == v { printf "%.2f\n", $1 - o }' "$1"
}
# between A B LOW HIGH: LOW <= A... for clip times (decimals): A within [LOW, HIGH].
within() { awk -v a="${1:-none}" -v l="$2" -v h="$3" 'BEGIN { exit !(a != "none" && a >= l && a <= h) }'; }

# write_gesture_config FILE: write_config's relative pointer with right click, double click
# and scroll on, at the values docs/clicks.md measures them with.
write_gesture_config() {
  write_config "$1" relative
  cat >>"$1" <<INI

[click]
right_seconds = 0.6
scroll_gain = 40
double_seconds = 0.8
INI
}
# key_times TRANSCRIPT CODE VALUE: clip times of CODE VALUE (BTN_RIGHT 1 ...), one a line.
key_times() {
  awk -v o="$origin" -v c="$2" -v v="$3" '$3 == c && $4 == v { printf "%.2f\n", $1 - o }' "$1"
}
