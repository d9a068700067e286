#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs what the VM system tests need (docs/testing.md), from Debian 12's packages: QEMU, a
# Debian kernel with headers so DKMS builds v4l2loopback for it, busybox and cpio for the
# initramfs, udev and libinput-tools for the libinput check, systemd, dbus and libpam-systemd
# for the service scenario's boot (systemd as PID 1, logind, a user manager). Called by
# .ci/install-deps; quick when all is there already. Runs apt-get as root, or through sudo
# when started by a user.
set -eu
packages="qemu-system-x86 linux-image-amd64 linux-headers-amd64 dkms v4l2loopback-dkms
  busybox-static cpio kmod udev libinput-tools systemd dbus libpam-systemd"
if [ "$(id -u)" -eq 0 ]; then as_root=""; else as_root="sudo"; fi

# v4l2loopback built for some installed kernel (DKMS builds it for each one with headers).
have_loopback() {
  for modules in /lib/modules/*/; do
    version=$(basename "$modules")
    [ -e "/boot/vmlinuz-$version" ] || continue
    modprobe -S "$version" --show-depends v4l2loopback >/dev/null 2>&1 && return 0
  done
  return 1
}

missing=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' $packages 2>/dev/null | awk '$1 != "ii" {print $2}')
installed=$(dpkg-query -W -f='${db:Status-Abbrev} ${Package}\n' $packages 2>/dev/null | wc -l)
if [ -z "$missing" ] && [ "$installed" -eq "$(echo $packages | wc -w)" ] && have_loopback; then
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update -qq
$as_root apt-get install -y -qq --no-install-recommends $packages
# The packages' triggers run DKMS for the kernel installed with them; a kernel that has headers
# but no module yet gets it here.
if ! have_loopback; then
  for headers in /lib/modules/*/build; do
    [ -d "$headers" ] && $as_root dkms autoinstall -k "$(basename "$(dirname "$headers")")"
  done
fi
have_loopback || { echo "install-deps: DKMS built no v4l2loopback for an installed kernel" >&2; exit 1; }
