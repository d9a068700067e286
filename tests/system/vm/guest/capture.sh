# SPDX-License-Identifier: MIT
# Capture formats (docs/testing.md): the rightdown clip from a YUYV camera and from an MJPEG
# camera (the same frames as 4:2:2 JPEGs at quality 85, as webcams send them), each through a
# fresh daemon in relative mode. The MJPEG camera's frames are decoded by libjpeg-turbo at 4/8
# scale (640x480 to the 320x240 the camera settings ask at least); the cursor moves right, then
# down, as on the YUYV camera, by motion.sh's limits. Each run's cost block (CPU of one core,
# latency) is printed for the record: under TCG it is the emulator's, tens of times the
# hardware's, so it is compared between the two runs and never checked. Under TCG a JPEG's
# decoding takes 100-200 ms, so the MJPEG camera plays the clip at a quarter of its speed (7.5
# frames a second): at the clip's 30 the daemon would take one frame in four or five, and the
# run would measure how the tracker copes with a hand moving five times as far between frames,
# not the capture path.
. "$here/motion.sh"  # motion_relative

scenario() {
  load_modules
  local format
  for format in yuyv mjpg; do
    [ "$format" = yuyv ] && camera=/dev/video0 || camera=/dev/video1
    [ "$format" = yuyv ] && speed=1 || speed=0.25
    write_config "$work/$format.ini" relative
    start_writer "rightdown.$format" "writer-$format.log" --wait --speed "$speed"
    start_recorder "events-$format.txt"
    start_daemon "$work/$format.ini" "$format"
    wait_ready
    go
    wait "$writer_pid"
    sleep 0.5
    stop "$daemon_pid" "$recorder_pid" "$listener_pid"
    echo "$format: $(grep -E 'capturing from|run cpu|latency handed' "$daemon_log" | tr -s ' ')"
    motion_relative "$work/events-$format.txt"
  done
  check "yuyv: captured as YUYV 640x480" grep -q 'YUYV 640x480' "$work/daemon-yuyv.log"
  check "mjpg: captured as MJPEG 640x480, decoded at 4/8 scale" \
    grep -q 'MJPG 640x480 (decoded on the CPU at 4/8 scale' "$work/daemon-mjpg.log"
}
