# SPDX-License-Identifier: MIT
# Start-up (docs/testing.md): READY=1 once uinput is open, with the camera open when there is
# one. The notify listener stops the daemon the moment READY=1 arrives and lists its open
# devices: both must be there. Without uinput (the module not loaded yet) and with a bad
# configuration file, raypoint run exits non-zero with the reason, sends no READY=1 and leaves no
# input device behind. Without a camera (no writer: the loopback node is no capture device) it
# is READY and waits for one; paused, it closes the camera, and resumed it opens it again.
scenario() {
  modprobe evdev || bad "modprobe evdev"
  load_loopback

  # No uinput yet: a camera (/dev/video0), but no /dev/uinput.
  camera=/dev/video0
  write_config "$work/no-uinput.ini" relative
  start_writer rightdown writer-no-uinput.log --loop
  expect_refusal no-uinput "$work/no-uinput.ini" '/dev/uinput'
  stop "$writer_pid"
  modprobe uinput || bad "modprobe uinput"

  # No camera yet: /dev/video1 has no writer, so it is no capture device. The service starts
  # anyway (READY=1, STATUS=waiting for a camera) rather than failing into a restart loop, and
  # opens the camera once a writer plays there. Paused, it closes the camera (no descriptor on
  # it in /proc/PID/fd); resumed, it opens it again.
  camera=/dev/video1
  write_config "$work/no-camera.ini" relative /dev/video1
  local socket="$work/no-camera.sock"
  start_daemon "$work/no-camera.ini" no-camera --control "$socket"
  wait_ready
  check "no camera: STATUS= says it waits" wait_for "$notify_log" ' STATUS=waiting for a camera' 10
  check "no camera: still running" kill -0 "$daemon_pid"
  start_writer rightdown writer-no-camera.log --loop
  check "no camera: opens it when it appears" wait_for "$daemon_log" 'camera found' 10
  check "no camera: frames arrive" eventually 10 frames_above "$socket" 0
  check "pause: replies paused" eq "$("$raypoint" ctl pause --control "$socket")" paused
  check "pause: the camera is closed" eventually 5 not_open "$daemon_pid" "$camera"
  local paused_frames
  paused_frames=$(frames_of "$socket")
  sleep 1
  check "pause: no frames while paused" eq "$(frames_of "$socket")" "$paused_frames"
  check "resume: replies resumed" eq "$("$raypoint" ctl toggle --control "$socket")" resumed
  check "resume: the camera is open again" eventually 5 is_open "$daemon_pid" "$camera"
  check "resume: frames again" eventually 10 frames_above "$socket" "$paused_frames"
  stop "$daemon_pid" "$listener_pid" "$writer_pid"

  # A bad configuration file: file:line and the key, before any device is opened.
  printf '[pointer]\nmode = relative\n\n[tracking]\nmin_area = 7\n' >"$work/bad.ini"
  expect_refusal bad-config "$work/bad.ini" "bad.ini:5: \\[tracking\\] min_area"

  # All there: READY=1 with the camera and uinput open at that moment.
  camera=/dev/video2
  write_config "$work/ready.ini" relative
  start_writer rightdown writer-ready.log --loop
  start_daemon "$work/ready.ini" ready
  wait_ready
  local open_at_ready
  open_at_ready=$(grep 'open at READY=1:' "$notify_log")
  echo "ready: $open_at_ready"
  check "ready: the camera was open at READY=1" grep -q " $camera\\b" <<<"$open_at_ready"
  check "ready: /dev/uinput was open at READY=1" grep -q ' /dev/uinput\b' <<<"$open_at_ready"
  check "ready: the virtual pointer exists" grep -q 'raypoint virtual pointer' /proc/bus/input/devices
  stop "$daemon_pid" "$listener_pid" "$writer_pid"
}

# eventually SECONDS COMMAND...: until the command succeeds, at most SECONDS.
eventually() {
  local deadline=$((SECONDS + $1))
  shift
  while [ "$SECONDS" -le "$deadline" ]; do
    "$@" && return 0
    sleep 0.1
  done
  return 1
}
# frames_of SOCKET: the frames the daemon has processed (ctl status).
frames_of() { "$raypoint" ctl status --control "$1" | awk '$1 == "frames:" { print $2 }'; }
frames_above() { [ "$(frames_of "$1")" -gt "$2" ] 2>/dev/null; }
# is_open PID DEVICE / not_open PID DEVICE: whether the process has a descriptor on the device.
is_open() { ls -l "/proc/$1/fd" 2>/dev/null | grep -q " -> $2\$"; }
not_open() { ! is_open "$@"; }

# expect_refusal NAME CONFIG REGEX: raypoint run exits non-zero, its error matches REGEX, no
# READY=1, no virtual pointer left.
expect_refusal() {
  local name=$1 config=$2 reason=$3 status
  start_daemon "$config" "$name"
  wait "$daemon_pid"
  status=$?
  sleep 0.2
  stop "$listener_pid"
  echo "$name: exit $status: $(head -3 "$daemon_log")"
  check "$name: exits non-zero ($status)" test "$status" -ne 0
  check "$name: says why (/$reason/)" grep -qE "$reason" "$daemon_log"
  check "$name: no READY=1" eval "! grep -q 'READY=1' '$notify_log'"
  check "$name: no virtual pointer left" eval "! grep -q 'raypoint virtual pointer' /proc/bus/input/devices"
}
