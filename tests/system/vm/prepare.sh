#!/bin/bash
# SPDX-License-Identifier: MIT
# The VM tests' fixture (CTest vm_prepare): checks the prerequisites, builds the initramfs for
# the newest installed kernel that has v4l2loopback, and renders the clips the scenarios play,
# as raw YUYV (and one as MJPEG). Writes VM_DIR/kernel.env, VM_DIR/initramfs.gz and
# VM_DIR/clips/*.yuyv, *.mjpg.
# usage: prepare.sh VM_DIR RENDER_SCENE LOOPBACK_WRITER
set -euo pipefail
vm_dir=$1
render=$2
writer=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
mkdir -p "$vm_dir/clips"
rm -f "$vm_dir/kernel.env" "$vm_dir/unavailable"
unavailable_file="$vm_dir/unavailable"

command -v qemu-system-x86_64 >/dev/null || unavailable "no qemu-system-x86_64"
command -v cpio >/dev/null || unavailable "no cpio"
[ -x /bin/busybox ] || unavailable "no /bin/busybox (busybox-static)"
ldd /bin/busybox >/dev/null 2>&1 && unavailable "/bin/busybox is linked dynamically (install busybox-static)"
find_kernel || unavailable "no /boot/vmlinuz-VERSION with a v4l2loopback module (linux-image-amd64, linux-headers-amd64, v4l2loopback-dkms)"
[ -r "$kernel_image" ] || unavailable "cannot read $kernel_image (Debian makes it root-only; run as root)"
echo "kernel $kernel_version ($kernel_image)"

# The initramfs only mounts the host's root over virtio-9p (with an overlay for a systemd boot)
# and hands over to it (guest/init): everything else, modprobe included, comes from the host's
# own files.
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
mkdir -p "$root"/{bin,dev,proc,sys,host,lower,rw,modules}
cp /bin/busybox "$root/bin/busybox"
cp "$here/guest/init" "$root/init"
chmod +x "$root/init"
for module in virtio_pci 9pnet_virtio 9p overlay; do
  modprobe -S "$kernel_version" --show-depends "$module" | awk '$1 == "insmod" {print $2}'
done | awk '!seen[$0]++' | while read -r file; do
  cp "$file" "$root/modules/"
  basename "$file" >> "$root/modules/order"
done
(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$vm_dir/initramfs.gz.new"
mv "$vm_dir/initramfs.gz.new" "$vm_dir/initramfs.gz"

# The clips: rendered once, converted to the raw frames raypoint-loopback-writer plays.
for clip in rightdown click drag rightclick doubleclick scroll; do
  out="$vm_dir/clips/$clip.yuyv"
  [ "$out" -nt "$render" ] && continue
  "$render" --preset "$clip" --out "$root/$clip" --no-masks >/dev/null
  "$writer" convert "$root/$clip/video.mp4" "$out.new"
  mv "$out.new" "$out"
done

# The capture scenario's MJPEG camera: rightdown's frames as JPEGs.
out="$vm_dir/clips/rightdown.mjpg"
if ! [ "$out" -nt "$render" ]; then
  "$render" --preset rightdown --out "$root/rightdown" --no-masks >/dev/null
  "$writer" convert "$root/rightdown/video.mp4" "$out.new" --mjpeg
  mv "$out.new" "$out"
fi

printf 'kernel_version=%s\nkernel_image=%s\n' "$kernel_version" "$kernel_image" > "$vm_dir/kernel.env"
echo "VM ready: $vm_dir"
