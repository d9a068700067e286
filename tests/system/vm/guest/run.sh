#!/bin/bash
# SPDX-License-Identifier: MIT
# In the VM, chrooted into the host's root (guest/init): the common set-up, then one scenario
# (guest/SCENARIO.sh, which defines scenario()), then the verdict in JOB/result: pass, fail
# REASON or skip REASON. Live files go to /run/work (tmpfs) and are copied to JOB/work at the
# end, where the host prints them on failure.
job=$1
. "$job/job.env"
export PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
export HOME=/run/home TMPDIR=/run/tmp XDG_RUNTIME_DIR=/run/user/0 XDG_CONFIG_HOME=/run/config
export XDG_CONFIG_DIRS=/run/none LANG=C.UTF-8
work=/run/work
mkdir -p "$HOME" "$TMPDIR" "$XDG_RUNTIME_DIR" "$XDG_CONFIG_HOME" "$work" "$job/work"
exec > >(tee -a "$job/guest.log") 2>&1
here="$source_dir/tests/system/vm/guest"
. "$here/common.sh"
. "$here/$scenario.sh"
echo "raypoint-vm: $scenario on $(uname -r), $(nproc) CPUs"
verdict=""
scenario
if [ -n "$verdict" ]; then
  :
elif [ "$failures" -eq 0 ]; then
  verdict=pass
else
  verdict="fail $failures check(s) failed: $first_failure"
fi
stop_all
cp -r "$work/." "$job/work/" 2>/dev/null
echo "raypoint-vm: verdict: $verdict"
echo "$verdict" > "$job/result"
sync
