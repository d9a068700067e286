# SPDX-License-Identifier: MIT
# Helpers for service.sh (sourced): the user's commands, the service's properties and journal,
# a clip played to the running service, and the unplug/replug cycles.

# step TEXT: progress on the console, with the guest's uptime (TCG is slow: where did it go?).
step() { echo "== $* (at $(cut -d' ' -f1 /proc/uptime) s)"; }

# as_user COMMAND...: as the logged-in user, with its runtime directory (systemctl --user and
# raypoint ctl reach the user manager and the daemon there).
as_user() {
  setpriv --reuid="$uid" --regid="$gid" --init-groups \
    env -i PATH="$PATH" HOME="/home/$user" USER="$user" LOGNAME="$user" LANG=C.UTF-8 \
    XDG_RUNTIME_DIR="/run/user/$uid" "$@"
}
service_property() { as_user systemctl --user show raypoint.service -p "$1" --value 2>/dev/null; }
# The service's journal: the daemon's lines and its user manager's about it.
service_journal() {
  journalctl --no-pager -o cat _SYSTEMD_USER_UNIT=raypoint.service + USER_UNIT=raypoint.service
}
# wait_journal REGEX SECONDS: until the service's journal has a line matching.
wait_journal() {
  local deadline=$((SECONDS + $2))
  while [ "$SECONDS" -le "$deadline" ]; do
    service_journal | grep -qE "$1" && return 0
    sleep 0.5
  done
  return 1
}
# eventually SECONDS COMMAND...: until the command succeeds, at most SECONDS.
eventually() {
  local deadline=$((SECONDS + $1))
  shift
  while [ "$SECONDS" -le "$deadline" ]; do
    "$@" && return 0
    sleep 0.2
  done
  return 1
}
# ctl status's "source:" line says REGEX.
status_says() { as_user raypoint ctl status 2>/dev/null | grep -qE "^source: .*$1"; }
# status_value KEY: the number after "KEY:" in ctl status ("camera losses: 3").
status_value() {
  as_user raypoint ctl status 2>/dev/null | awk -v k="$1:" 'index($0, k) == 1 { print $NF }'
}
has_camera() {
  as_user raypoint ctl status 2>/dev/null | grep '^source: ' | grep -qv 'waiting for a camera'
}

# service_config MIRROR: the user's raypoint.ini: relative motion, the camera found by itself.
service_config() {
  cat >"$work/user.ini" <<INI
# raypoint in the VM, as the user service reads it.
[pointer]
mode = relative
mirror = $1

[camera]
device = auto
INI
  as_user cp "$work/user.ini" "$config_dir/raypoint.ini"
}

# play_to_service CLIP NAME [status]: the clip on $camera, to the running service, once it has
# opened the camera; its events in events-NAME.txt (a recorder on the service's virtual
# pointer). With "status", systemctl --user status 4 s into the clip, in status-NAME.txt.
play_to_service() {
  start_writer "$1" "writer-$2.log" --wait
  start_recorder "events-$2.txt"
  eventually 30 has_camera || bad "$2: the service did not open $camera ($(status_says . && as_user raypoint ctl status | grep source))"
  go
  # Not during a clip with a click: under TCG, systemctl's seconds of CPU make the daemon drop
  # frames (a push went unseen so).
  if [ "${3:-}" = status ]; then
    sleep 4
    as_user systemctl --user status raypoint.service --no-pager >"$work/status-$2.txt" 2>&1
  fi
  wait "$writer_pid"
  sleep 0.5
  stop "$recorder_pid"
}

# unplug: the node gone, as when a webcam's cable is pulled. v4l2loopback removes a node only
# with its module, and only once nothing holds it open: the daemon lets the camera go when it
# stops delivering frames, so this retries until the module is out.
unplug() {
  eventually 30 modprobe -r v4l2loopback 2>/dev/null
}

# replug N: N cycles of plug in (modprobe v4l2loopback), play the drag clip until 6.0 s (the
# button is held from the push at 4.0 s), the stream stops and the node goes (unplug). Each
# cycle the service must open the camera again and press; every press must be released.
replug() {
  local cycles=$1 i reopened=0 pressed=0 lost_before pid restarts
  start_recorder events-replug.txt
  unplug || bad "replug: cannot remove v4l2loopback before the cycles"
  lost_before=$(status_value 'camera losses')
  pid=$(service_property MainPID)
  restarts=$(service_property NRestarts)
  camera=/dev/video0
  : >"$work/replug-origins.txt"
  for i in $(seq 1 "$cycles"); do
    modprobe v4l2loopback devices=1 video_nr=0 exclusive_caps=1 card_label="raypoint replug" ||
      bad "replug $i: modprobe v4l2loopback"
    udevadm settle
    start_writer drag "writer-replug-$i.log" --wait --until 6.0
    if eventually 30 has_camera; then reopened=$((reopened + 1)); fi
    go
    echo "$i $origin" >>"$work/replug-origins.txt"
    wait "$writer_pid"
    eventually 15 status_says 'waiting for a camera' || bad "replug $i: no loss reported"
    unplug || bad "replug $i: v4l2loopback stays in use ($(lsmod | grep v4l2loopback))"
    [ -n "$(awk -v o="$origin" '$3 == "BTN_LEFT" && $4 == 1 && $1 >= o' "$work/events-replug.txt")" ] &&
      pressed=$((pressed + 1))
  done
  sleep 1
  stop "$recorder_pid"
  local t="$work/events-replug.txt" presses releases losses last
  presses=$(count "$t" 'BTN_LEFT 1$')
  releases=$(count "$t" 'BTN_LEFT 0$')
  last=$(awk '$3 == "BTN_LEFT" { v = $4 } END { print v }' "$t")
  losses=$(($(status_value 'camera losses') - lost_before))
  echo "replug: $cycles cycles: camera reopened $reopened, cycles with a press $pressed, presses $presses, releases $releases, camera losses $losses"
  check "replug: the service opened the camera again in every cycle ($reopened/$cycles)" \
    eq "$reopened" "$cycles"
  check "replug: every press released ($presses presses, $releases releases)" \
    eq "$presses" "$releases"
  check "replug: the last button event is a release (${last:-none})" eq "${last:-0}" 0
  check "replug: a press in every cycle ($pressed/$cycles)" eq "$pressed" "$cycles"
  check "replug: each unplug reported as a loss ($losses)" ge "$losses" "$cycles"
  check "replug: the service still active" eq "$(service_property ActiveState)" active
  # Each unplug is a 2 s stall first: the daemon must keep the watchdog fed through it.
  check "replug: the same daemon throughout, no restart (pid $(service_property MainPID), was $pid; NRestarts $(service_property NRestarts), was $restarts)" \
    eval "[ \"\$(service_property MainPID)\" = $pid ] && [ \"\$(service_property NRestarts)\" = $restarts ]"
}
