#!/bin/bash
# SPDX-License-Identifier: MIT
# One VM system test (CTest vm_SCENARIO): boots Debian's kernel under QEMU with the initramfs
# vm_prepare built, the host's root shared read-only, runs guest/SCENARIO.sh inside it and
# turns the guest's verdict into the exit code. On failure prints the guest's console and logs.
# usage: run_scenario.sh SCENARIO VM_DIR SOURCE_DIR RAYPOINT TOOLS_DIR
# (TOOLS_DIR: where raypoint-loopback-writer and the other test programs are.)
set -uo pipefail
scenario=$1
vm_dir=$(realpath "$2")
source_dir=$(cd "$3" && pwd)
raypoint_binary=$(realpath "$4")
tools_dir=$(cd "$5" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
boot_timeout=${RAYPOINT_VM_TIMEOUT:-240}  # s for the whole boot; a scenario takes 20-60 s
# A scenario may ask for another boot and its own timeout with a line "# vm-boot: BOOT SECONDS"
# (BOOT: chroot, the default, or systemd: systemd as PID 1 on an overlay of the host's root,
# guest/init). RAYPOINT_VM_TIMEOUT still wins.
read -r boot scenario_timeout < <(sed -n 's/^# vm-boot: //p' "$here/guest/$scenario.sh" 2>/dev/null)
boot=${boot:-chroot}
[ -z "${RAYPOINT_VM_TIMEOUT:-}" ] && [ -n "${scenario_timeout:-}" ] && boot_timeout=$scenario_timeout
# A scenario that installs the service's package gets it from RAYPOINT_VM_DEB (a path to the
# raypoint_*.deb CPack built).
service_deb=""
if [ -n "${RAYPOINT_VM_DEB:-}" ]; then
  [ -f "$RAYPOINT_VM_DEB" ] || unavailable "RAYPOINT_VM_DEB=$RAYPOINT_VM_DEB is no file"
  service_deb=$(realpath "$RAYPOINT_VM_DEB")
fi

[ -f "$vm_dir/kernel.env" ] ||
  unavailable "$(cat "$vm_dir/unavailable" 2>/dev/null || echo "vm_prepare has not prepared $vm_dir")"
. "$vm_dir/kernel.env"
command -v qemu-system-x86_64 >/dev/null || unavailable "no qemu-system-x86_64"
if [ "$boot" = systemd ]; then
  [ -x /lib/systemd/systemd ] || unavailable "no /lib/systemd/systemd to boot (systemd)"
  [ -n "$service_deb" ] || unavailable "vm_$scenario installs the package: set RAYPOINT_VM_DEB"
fi

# The job directory: the guest sees it at the same path (the host's root is shared), written
# through a second, writable share. Absolute and without spaces, for the kernel command line.
job=$(mktemp -d "${TMPDIR:-/tmp}/raypoint-vm-$scenario.XXXXXX")
job=$(cd "$job" && pwd -P)
qemu_pid=""
cleanup() {
  [ -n "$qemu_pid" ] && kill "$qemu_pid" 2>/dev/null
  [ -n "${RAYPOINT_VM_KEEP:-}" ] && { echo "kept $job"; return; }
  rm -rf "$job"
}
trap cleanup EXIT
cat > "$job/job.env" <<ENV
scenario=$scenario
source_dir=$source_dir
raypoint_binary=$raypoint_binary
tools_dir=$tools_dir
vm_dir=$vm_dir
service_deb=$service_deb
replug_cycles=${RAYPOINT_VM_REPLUG_CYCLES:-20}
ENV

start=$(date +%s.%N)
# -nodefaults: no network card (no iPXE ROM to wait for), no display; the serial console is
# the guest's output. 1.5 GiB holds the daemon, the clips (70 MiB each as raw frames), udev, and
# for a systemd boot the overlay's tmpfs and the journal.
timeout --signal=KILL "$boot_timeout" qemu-system-x86_64 $(qemu_accel) -nodefaults -no-user-config \
  -m 1536 -smp 2 -display none -no-reboot -serial "file:$job/console.log" \
  -kernel "$kernel_image" -initrd "$vm_dir/initramfs.gz" \
  -append "console=ttyS0 quiet panic=-1 raypoint.boot=$boot raypoint.job=$job raypoint.script=$here/guest/run.sh" \
  -virtfs "local,path=/,mount_tag=hostroot,readonly=on,security_model=none,multidevs=remap" \
  -virtfs "local,path=$job,mount_tag=job,security_model=none" \
  >"$job/qemu.log" 2>&1 &
qemu_pid=$!
wait "$qemu_pid"
qemu_status=$?
qemu_pid=""
seconds=$(awk "BEGIN {printf \"%.1f\", $(date +%s.%N) - $start}")

result=$(cat "$job/result" 2>/dev/null)
case "$result" in
  pass)
    echo "vm_$scenario: passed in a $seconds s boot ($kernel_version, $(qemu_accel))"
    grep -h '^ok ' "$job/guest.log" 2>/dev/null
    exit 0
    ;;
  skip*)
    echo "SKIP: vm_$scenario: ${result#skip }"
    [ "${CI:-}" = "true" ] && exit 1
    exit 77
    ;;
esac
if [ "$qemu_status" -eq 137 ]; then
  echo "FAIL: vm_$scenario: no verdict after the boot timeout of $boot_timeout s (QEMU killed)"
else
  echo "FAIL: vm_$scenario: ${result:-no verdict from the guest (QEMU exited $qemu_status after $seconds s)}"
fi
echo "----- guest console ($job/console.log)"
cat "$job/console.log" 2>/dev/null
echo "----- QEMU"
cat "$job/qemu.log"
for log in "$job"/work/*.log "$job"/work/*.txt; do
  [ -f "$log" ] || continue
  echo "----- $(basename "$log") (last 60 lines)"
  tail -n 60 "$log"
done
exit 1
