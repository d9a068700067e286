#!/bin/bash
# SPDX-License-Identifier: MIT
# The user unit as this build configures it must pass `systemd-analyze verify`, with ExecStart
# pointing at this build's raypoint (verify checks that the executable exists). Also prints the
# unit's exposure score from `systemd-analyze security --offline`. Exit 77 (skipped) where there
# is no systemd-analyze.
#   test_unit_file.sh BUILD/packaging/raypoint.service BUILD/raypoint [MAN_PAGE...]
set -euo pipefail

unit=${1:?usage: test_unit_file.sh UNIT RAYPOINT [MAN_PAGE...]}
raypoint=${2:?usage: test_unit_file.sh UNIT RAYPOINT [MAN_PAGE...]}
shift 2

if ! command -v systemd-analyze >/dev/null 2>&1; then
    echo "SKIP: systemd-analyze not found (Debian package systemd)"
    exit 77
fi
[ -f "$unit" ] || { echo "FAIL: no unit file $unit"; exit 1; }
[ -x "$raypoint" ] || { echo "FAIL: no executable $raypoint"; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The unit's name is what verify reports and what the security check looks at.
copy=$work/raypoint.service
exec_start=$(sed -n 's/^ExecStart=\([^ ]*\).*/\1/p' "$unit")
sed "s|^ExecStart=[^ ]*|ExecStart=$raypoint|" "$unit" >"$copy"
echo "installed ExecStart: $exec_start; verified with: $raypoint"

# A user unit is verified by a user manager's rules. systemd-analyze --user wants a runtime
# directory; CI and containers often have none, so give it one.
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$work/runtime}
mkdir -p "$XDG_RUNTIME_DIR"
chmod 700 "$XDG_RUNTIME_DIR"

# verify runs `man` on each Documentation=man:... entry: offer it this build's pages, as they
# will be installed. Without man (package man-db) that check is left out.
man_option=--man=yes
if command -v man >/dev/null 2>&1 && [ $# -gt 0 ]; then
    for page in "$@"; do
        section=${page##*.}
        mkdir -p "$work/man/man$section"
        cp "$page" "$work/man/man$section/"
    done
    export MANPATH=$work/man
else
    man_option=--man=no
fi

# --user: checked as a user manager would load it (graphical-session.target is a user unit).
status=0
output=$(systemd-analyze --user verify $man_option "$copy" 2>&1) || status=$?
echo "$output"
# verify warns on stderr and still exits 0 for some problems: any line naming our unit fails.
if [ $status -ne 0 ] || grep -q "raypoint.service" <<<"$output"; then
    echo "FAIL: systemd-analyze verify rejected the unit (status $status)"
    exit 1
fi
echo "PASS: systemd-analyze verify"

# The exposure score (0 = fully sandboxed, 10 = not at all). --offline reads the file alone;
# it judges as for a system service, so it counts what a user manager cannot apply.
if systemd-analyze security --help 2>&1 | grep -q -- "--offline"; then
    score=$(systemd-analyze security --offline=yes --no-pager "$copy" 2>&1 |
            sed -n 's/.*Overall exposure level for raypoint.service: *\([0-9.]*\).*/\1/p')
    if [ -n "$score" ]; then
        echo "exposure score: $score"
        # The sandbox above gives about 2; over 5 ("MEDIUM") means a directive went missing.
        if awk -v s="$score" 'BEGIN { exit !(s > 5.0) }'; then
            echo "FAIL: exposure $score is over 5.0"
            exit 1
        fi
    fi
fi
