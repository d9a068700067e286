# SPDX-License-Identifier: MIT
# vm-boot: systemd 1800
# The service as users run it (docs/testing.md, docs/reliability.md): systemd is PID 1 (an
# overlay of the host's root, guest/init), the package CPack built is installed with dpkg, an
# ordinary user in the video group logs in on tty1 (an autologin getty: a seat0 session, so
# logind gives it the uaccess ACLs of 70-raypoint-uinput.rules), and its user manager runs
# `systemctl --user enable --now raypoint` with the unit's sandbox as shipped. Then, each with
# its checks: a clip's motion and click through the service; `systemctl --user status` shows
# STATUS=; `systemctl --user reload` applies a changed INI and keeps the running one when the
# new one is invalid; the watchdog restarts a stopped daemon; `systemd-analyze security --user`;
# and 20 unplug/replug cycles of v4l2loopback with the button held at each unplug.
user=raypoint-user
# replug_cycles: from job.env (RAYPOINT_VM_REPLUG_CYCLES on the host, 20 by default).
. "$here/service_lib.sh"

scenario() {
  if [ "$(cat /proc/1/comm)" != systemd ]; then
    bad "PID 1 is $(cat /proc/1/comm), not systemd"
    return
  fi
  if [ -z "$service_deb" ]; then
    verdict="skip no package to install: set RAYPOINT_VM_DEB to the raypoint_*.deb CPack built"
    return
  fi
  echo "systemd: $(systemctl --version | head -1); package: $(basename "$service_deb")"
  service_steps
  step "done"
  as_user systemctl --user status raypoint.service --no-pager >"$work/status-end.txt" 2>&1
  # The guest's whole journal, for a failure's diagnosis (run_scenario.sh shows work/'s files).
  journalctl --no-pager -o short-monotonic >"$work/journal.txt" 2>&1
}

service_steps() {
  step "install the package"
  install_package || return
  step "log in"
  log_in || return
  step "enable --now"
  enable_service || return
  service_sandbox
  step "a click"
  service_clip_click
  step "reload"
  service_reload
  service_status
  step "watchdog"
  service_watchdog
  service_security
  step "$replug_cycles replug cycles"
  replug "$replug_cycles"
}

# The package, as a user's machine gets it: dpkg -i, whose postinst loads uinput and has udev
# apply 70-raypoint-uinput.rules (the uaccess tag) to /dev/uinput.
install_package() {
  modprobe evdev || bad "modprobe evdev"
  # The cameras for the video group only: without this rule the seat's user would also get an
  # ACL on them (uaccess), and the group's access under PrivateUsers=yes would go untested.
  printf 'SUBSYSTEM=="video4linux", TAG-="uaccess"\n' >/etc/udev/rules.d/72-raypoint-vm.rules
  udevadm control --reload
  # Three nodes for the three clips before the replug cycles (one writer a node).
  load_loopback
  udevadm settle --timeout=60
  # man-db's trigger would rebuild the whole manual index: minutes under TCG, and not what is
  # tested. Its switch is this file (in the overlay; the host's stays).
  rm -f /var/lib/man-db/auto-update
  step "dpkg -i"
  if ! timeout 300 dpkg -i "$service_deb" >"$work/dpkg.log" 2>&1; then
    bad "dpkg -i $(basename "$service_deb"): $(tail -3 "$work/dpkg.log")"
    return 1
  fi
  udevadm settle --timeout=60
  check "package: the unit is installed" test -f /usr/lib/systemd/user/raypoint.service
  check "package: its postinst loaded uinput" test -c /dev/uinput
  check "package: udev tagged /dev/uinput uaccess" \
    eval "udevadm info /dev/uinput | grep -q '^E: CURRENT_TAGS=.*:uaccess:'"
  check "package: the cameras are the video group's" \
    eval "[ \"\$(stat -c %G /dev/video0)\" = video ]"
}

# An ordinary user in the video group, logged in on tty1 by an autologin getty: pam_systemd
# opens a seat0 session, logind starts user@UID.service and gives the session's user the
# uaccess ACLs.
log_in() {
  useradd --create-home --groups video --shell /bin/bash "$user" || { bad "useradd"; return 1; }
  uid=$(id -u "$user")
  gid=$(id -g "$user")
  config_dir=/home/$user/.config/raypoint
  as_user mkdir -p "$config_dir"
  service_config false
  mkdir -p /run/systemd/system/getty@tty1.service.d
  cat >/run/systemd/system/getty@tty1.service.d/autologin.conf <<UNIT
[Service]
ExecStart=
ExecStart=-/sbin/agetty --autologin $user --noclear %I linux
UNIT
  systemctl daemon-reload
  systemctl start getty@tty1.service || bad "systemctl start getty@tty1"
  if ! eventually 120 test -S "/run/user/$uid/systemd/private"; then
    bad "login: no user manager for $user ($(loginctl list-sessions --no-legend))"
    return 1
  fi
  loginctl list-sessions --no-legend >"$work/sessions.txt"
  echo "login: $(cat "$work/sessions.txt")"
  check "login: $user has a session on seat0" grep -q " $user seat0 " "$work/sessions.txt"
  check "login: the session is active" \
    eventually 30 eval "loginctl show-user $user -p State --value | grep -qx active"
  check "login: $user may write /dev/uinput (uaccess ACL)" as_user test -w /dev/uinput
  check "login: $user may read /dev/video0, through the group only (no ACL: $(ls -l /dev/video0 | cut -c1-11))" \
    eval "as_user test -r /dev/video0 && [ \"\$(ls -l /dev/video0 | cut -c11)\" != + ]"
  check "login: $user is in the video group" eval "id -nG $user | grep -qw video"
  eventually 60 user_manager_running || bad "login: the user manager is $(as_user systemctl --user is-system-running)"
  return 0
}
user_manager_running() {
  case "$(as_user systemctl --user is-system-running 2>/dev/null)" in
    running | degraded) return 0 ;;
  esac
  return 1
}

# systemctl --user enable --now: started once READY=1 (uinput open; no camera yet: the
# service waits for one).
enable_service() {
  if ! as_user systemctl --user enable --now raypoint.service >"$work/enable.txt" 2>&1; then
    bad "enable --now: $(cat "$work/enable.txt"); $(service_journal | tail -5)"
    return 1
  fi
  check "service: active after enable --now" eq "$(service_property ActiveState)" active
  check "service: enabled" eq "$(as_user systemctl --user is-enabled raypoint.service)" enabled
  check "service: waits for a camera" eventually 20 status_says 'waiting for a camera'
  return 0
}

# The click clip through the service: the cursor moves right (4.0-5.5 s) and one push
# (6.0-6.7 s) gives one press and one release.
service_clip_click() {
  camera=/dev/video0
  play_to_service click click
  local t="$work/events-click.txt" presses releases moved press
  presses=$(count "$t" 'BTN_LEFT 1$')
  releases=$(count "$t" 'BTN_LEFT 0$')
  moved=$(sum "$t" REL_X 3.9 6.0)
  press=$(button_times "$t" 1 | head -1)
  echo "click: REL_X $moved over 3.9-6.0 s; $presses press(es) (first at ${press:-none} s), $releases release(s)"
  check "click: the cursor moves right (REL_X $moved >= 400)" ge "$moved" 400
  check "click: exactly one press ($presses)" eq "$presses" 1
  check "click: exactly one release ($releases)" eq "$releases" 1
  check "click: the press during the push, 6.0-7.3 s (${press:-none})" within "$press" 6.0 7.3
}

# systemctl --user status, taken during the mirrored clip (service_reload), shows the daemon's STATUS= line: the
# tracker's state, the frame rate and the CPU.
service_status() {
  local line
  line=$(grep -m1 '^ *Status: "' "$work/status-mirrored.txt")
  line=${line#"${line%%[! ]*}"}
  echo "status: $line"
  check "status: systemctl --user status shows STATUS= with a state and frames ($line)" \
    eval "grep -qE '^ *Status: \"(initializing|searching|tracking|validating|recovering)[^\"]*, [1-9][0-9.]* fps, CPU [0-9.]+%\"' '$work/status-mirrored.txt'"
}

# The sandbox is in force, not only written down: the daemon runs in a user namespace and a
# network namespace of its own (PrivateUsers=, PrivateNetwork=), sees / read-only
# (ProtectSystem=strict), has no capabilities, NoNewPrivs and a seccomp filter, and keeps the
# video group (through which alone it reads the cameras here: install_package).
service_sandbox() {
  local pid video
  pid=$(service_property MainPID)
  video=$(getent group video | cut -d: -f3)
  grep -E '^(Uid|Groups|NoNewPrivs|CapEff|Seccomp):' "/proc/$pid/status" | tr '\t' ' ' >"$work/sandbox.txt"
  echo "sandbox: $(tr '\n' ';' <"$work/sandbox.txt")"
  check "sandbox: a user namespace of its own (PrivateUsers=yes)" own_namespace "$pid" user
  check "sandbox: a network namespace of its own (PrivateNetwork=yes)" own_namespace "$pid" net
  check "sandbox: / is read-only (ProtectSystem=strict)" root_read_only "$pid"
  check "sandbox: runs as $user ($uid)" grep -qE "^Uid: $uid " "$work/sandbox.txt"
  check "sandbox: no capabilities" grep -qE '^CapEff: 0+$' "$work/sandbox.txt"
  check "sandbox: NoNewPrivs" grep -qx 'NoNewPrivs: 1' "$work/sandbox.txt"
  check "sandbox: a seccomp filter" grep -qx 'Seccomp: 2' "$work/sandbox.txt"
  check "sandbox: still in the video group ($video)" grep -qE "^Groups:.* $video( |$)" "$work/sandbox.txt"
}
own_namespace() { [ "$(readlink "/proc/$1/ns/$2")" != "$(readlink "/proc/1/ns/$2")" ]; }
root_read_only() { awk '$5 == "/" { print $6 }' "/proc/$1/mountinfo" | grep -q '^ro'; }

# A changed INI (mirror on: the hand's right is the cursor's left) applied by
# `systemctl --user reload`, without a restart; then an invalid one, rejected with the running
# configuration kept (still mirrored) and the daemon still the same process.
service_reload() {
  local pid
  pid=$(service_property MainPID)
  service_config true
  as_user systemctl --user reload raypoint.service || bad "reload: systemctl --user reload failed"
  check "reload: the daemon says so" wait_journal 'configuration reloaded' 20
  camera=/dev/video1
  play_to_service rightdown mirrored status
  local moved
  moved=$(sum "$work/events-mirrored.txt" REL_X 3.9 7.4)
  echo "reload: mirrored, REL_X $moved over the right stretch"
  check "reload: applied, the cursor moves left (REL_X $moved <= -600)" le "$moved" -600
  check "reload: the same process ($pid)" eq "$(service_property MainPID)" "$pid"

  printf '[pointer]\nmode = sideways\nmirror = false\n' >"$work/invalid.ini"
  as_user cp "$work/invalid.ini" "$config_dir/raypoint.ini"
  as_user systemctl --user reload raypoint.service || bad "reload: systemctl --user reload failed"
  check "invalid: rejected, the running configuration kept" \
    wait_journal 'reload failed, keeping the running configuration: .*mode' 20
  check "invalid: the service stays active" eq "$(service_property ActiveState)" active
  check "invalid: the same process ($pid)" eq "$(service_property MainPID)" "$pid"
  camera=/dev/video2
  play_to_service rightdown kept
  moved=$(sum "$work/events-kept.txt" REL_X 3.9 7.4)
  echo "invalid: REL_X $moved over the right stretch"
  check "invalid: still mirrored, the cursor moves left (REL_X $moved <= -600)" le "$moved" -600
  service_config false
  as_user systemctl --user reload raypoint.service || bad "reload: systemctl --user reload failed"
  check "reload: the daemon kept its own network namespace" own_namespace "$pid" net
}

# The watchdog: the unit's WatchdogSec, then SIGSTOP the daemon (a frame loop that no longer
# turns). systemd must kill it and start a new one, which gets READY again.
service_watchdog() {
  local watchdog pid restarts new_pid
  watchdog=$(service_property WatchdogUSec)
  pid=$(service_property MainPID)
  restarts=$(service_property NRestarts)
  check "watchdog: WatchdogSec=5 ($watchdog)" eq "$watchdog" 5s
  kill -STOP "$pid"
  local stopped=$SECONDS
  eventually 90 restarted "$pid" || true
  new_pid=$(service_property MainPID)
  echo "watchdog: pid $pid stopped; after $((SECONDS - stopped)) s pid ${new_pid:-none}, NRestarts $(service_property NRestarts)"
  check "watchdog: systemd says the watchdog fired" wait_journal 'Watchdog timeout' 5
  check "watchdog: a new daemon ($new_pid, was $pid)" restarted "$pid"
  check "watchdog: one restart (NRestarts $(service_property NRestarts), was $restarts)" \
    eq "$(service_property NRestarts)" $((restarts + 1))
  check "watchdog: the old one is gone" eval "! kill -0 $pid 2>/dev/null"
  kill -CONT "$pid" 2>/dev/null
}
restarted() {
  local now
  now=$(service_property MainPID)
  [ -n "$now" ] && [ "$now" != 0 ] && [ "$now" != "$1" ] &&
    [ "$(service_property ActiveState)" = active ]
}

# systemd-analyze security --user, inside the VM, against the running user manager.
service_security() {
  as_user systemd-analyze security --user raypoint.service --no-pager >"$work/security.txt" 2>&1
  local overall score
  overall=$(grep -m1 'Overall exposure level' "$work/security.txt")
  score=$(sed -n 's/.*Overall exposure level for raypoint.service: \([0-9.]*\).*/\1/p' "$work/security.txt")
  echo "security: ${overall:-no score ($(tail -2 "$work/security.txt"))}"
  check "security: an exposure score ($score), under 5" \
    eval "[ -n '$score' ] && awk -v s='$score' 'BEGIN { exit !(s < 5) }'"
}
