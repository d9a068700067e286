# SPDX-License-Identifier: MIT
# Shared by prepare.sh and run_scenario.sh (sourced): what the VM needs and how to say it is
# missing.

# A missing prerequisite: skipped (77) on a developer's machine, a failure under CI=true,
# where install-deps should have provided everything.
unavailable() {
  # prepare.sh keeps the reason for the scenarios, which then give the same one.
  [ -n "${unavailable_file:-}" ] && echo "$*" >"$unavailable_file"
  if [ "${CI:-}" = "true" ]; then
    echo "FAIL: $* (CI=true: a missing prerequisite is a failure; .ci/install-deps installs it)"
    exit 1
  fi
  echo "SKIP: $* (tests/system/vm/install-deps.sh installs what the VM tests need)"
  exit 77
}

# The newest installed Debian kernel with v4l2loopback built for it: sets kernel_version and
# kernel_image. Never the running kernel's version: the host may run any kernel (a container's).
find_kernel() {
  kernel_version=""
  for image in $(ls /boot/vmlinuz-* 2>/dev/null | sort -V -r); do
    local version=${image#/boot/vmlinuz-}
    if modprobe -S "$version" --show-depends v4l2loopback >/dev/null 2>&1; then
      kernel_version=$version
      kernel_image=$image
      return 0
    fi
  done
  return 1
}

# TCG unless KVM can really run a guest: a host that is itself a nested guest without vmx/svm
# (or with the kvm_pvm module) has /dev/kvm, but a kernel under it stops in decompression.
qemu_accel() {
  [ -n "${RAYPOINT_VM_ACCEL:-}" ] && { echo "$RAYPOINT_VM_ACCEL"; return; }
  if [ -w /dev/kvm ] && grep -qE '^flags.* (vmx|svm)( |$)' /proc/cpuinfo &&
    ! grep -q '^kvm_pvm ' /proc/modules 2>/dev/null; then
    echo "-accel kvm -cpu host"
  else
    echo "-accel tcg -cpu max"
  fi
}
