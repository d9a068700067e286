# SPDX-License-Identifier: MIT
# The system tests that skip on a machine without devices (uinput_roundtrip, v4l2_capture) run
# here for real: on uinput, on vivid (the kernel's own test camera) and on the loopback node
# fed by a writer. Skipping (77) counts as a failure in the VM.
scenario() {
  load_modules
  # vivid: a webcam-like capture node only, at /dev/video5 (the loopback has /dev/video0).
  modprobe vivid n_devs=1 node_types=0x1 vid_cap_nr=5 || bad "modprobe vivid"
  run_test uinput_roundtrip "$tools/test_uinput_roundtrip"
  RAYPOINT_TEST_CAMERA=/dev/video5 run_test "v4l2_capture on vivid" "$tools/test_v4l2_capture"
  start_writer rightdown writer.log --loop
  RAYPOINT_TEST_CAMERA=$camera run_test "v4l2_capture on v4l2loopback" "$tools/test_v4l2_capture"
  stop "$writer_pid"
}

# run_test NAME COMMAND...: passes only on exit 0.
run_test() {
  local name=$1 status
  shift
  "$@" >"$work/${name// /_}.txt" 2>&1
  status=$?
  sed "s/^/  $name: /" "$work/${name// /_}.txt" | tail -n 12
  check "$name: exit $status (0 = passed; 77 = skipped, a failure here)" test "$status" -eq 0
}
