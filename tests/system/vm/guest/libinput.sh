# SPDX-License-Identifier: MIT
# libinput sees it (docs/testing.md): with udev running in the VM (it tags input devices, as on
# a desktop), `libinput list-devices` lists the virtual pointer with the pointer capability, in
# both modes.
scenario() {
  if ! command -v libinput >/dev/null || [ ! -x /lib/systemd/systemd-udevd ]; then
    verdict="skip no libinput or systemd-udevd on the host (libinput-tools, udev)"
    return
  fi
  load_modules
  # udevd handles the uevents of devices made from now on. (udevadm trigger, settle and control
  # do nothing in a chroot, so the database entry is what the script waits for.)
  /lib/systemd/systemd-udevd --daemon || bad "systemd-udevd did not start"
  for mode in relative absolute; do
    [ "$mode" = relative ] && camera=/dev/video0 || camera=/dev/video1
    write_config "$work/$mode.ini" "$mode"
    start_writer rightdown "writer-$mode.log" --loop
    start_daemon "$work/$mode.ini" "$mode"
    wait_ready
    check "$mode: udev tagged the device as an input device" wait_tagged
    libinput list-devices >"$work/libinput-$mode.txt" 2>&1
    # The block of our device: from its "Device:" line to the next blank line.
    local block
    block=$(awk '/^Device: +raypoint virtual pointer$/ {on = 1} on && /^$/ {exit} on' \
      "$work/libinput-$mode.txt")
    echo "$mode:"
    sed 's/^/  /' <<<"$block"
    check "$mode: libinput lists the device" test -n "$block"
    check "$mode: libinput classifies it as a pointer" \
      grep -qE '^Capabilities: +pointer( |$)' <<<"$block"
    stop "$daemon_pid" "$listener_pid" "$writer_pid"
  done
}

# wait_tagged: until udev's database has the virtual pointer's event node with ID_INPUT=1,
# which libinput needs to take a device.
wait_tagged() {
  local deadline=$((SECONDS + 60)) event
  while [ "$SECONDS" -le "$deadline" ]; do
    for event in /sys/class/input/event*; do
      [ "$(cat "$event/device/name" 2>/dev/null)" = "raypoint virtual pointer" ] || continue
      grep -qs '^E:ID_INPUT=1$' "/run/udev/data/c$(cat "$event/dev")" && return 0
    done
    sleep 0.2
  done
  return 1
}
