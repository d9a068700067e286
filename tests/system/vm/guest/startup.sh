# SPDX-License-Identifier: MIT
# Start-up (docs/testing.md): READY=1 only once the camera and uinput are open. The notify
# listener stops the daemon the moment READY=1 arrives and lists its open devices: both must be
# there. Without a camera (no writer: the loopback node is no capture device), without uinput
# (the module not loaded yet) and with a bad configuration file, raypoint run exits non-zero
# with the reason, sends no READY=1 and leaves no input device behind.
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

  # No camera: /dev/video1 has no writer, so it is no capture device.
  write_config "$work/no-camera.ini" relative /dev/video1
  expect_refusal no-camera "$work/no-camera.ini" /dev/video1

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
