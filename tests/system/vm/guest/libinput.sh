# libinput sees it (docs/testing.md): with udev running in the VM (it tags input devices, as on
# a desktop), `libinput list-devices` lists the virtual pointer with the pointer capability, in
# both modes.
scenario() {
  load_modules
  /lib/systemd/systemd-udevd --daemon || bad "systemd-udevd did not start"
  udevadm trigger --action=add
  udevadm settle --timeout=60
  for mode in relative absolute; do
    [ "$mode" = relative ] && camera=/dev/video0 || camera=/dev/video1
    write_config "$work/$mode.ini" "$mode"
    start_writer rightdown "writer-$mode.log" --loop
    start_daemon "$work/$mode.ini" "$mode"
    wait_ready
    udevadm settle --timeout=60
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
  udevadm control --exit
}
