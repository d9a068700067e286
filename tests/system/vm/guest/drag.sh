# SPDX-License-Identifier: MIT
# Drag (docs/testing.md): the drag clip (a push at 4.0 s held while the hand moves right
# 5.3-6.5 s, pulled back at 6.8 s) gives one press, then motion, then one release, in that
# order: nothing moves before the press, the motion between press and release is at least half
# the host's figure (793 px), the release comes after it.
scenario() {
  load_modules
  write_config "$work/relative.ini" relative
  run_clip drag "$work/relative.ini" drag
  local t="$work/events-drag.txt" presses releases order
  presses=$(count "$t" 'BTN_LEFT 1$')
  releases=$(count "$t" 'BTN_LEFT 0$')
  # The motion before the press, while it is down, and after the release.
  order=$(awk '$3 == "BTN_LEFT" { phase += 1; next }
               $3 == "REL_X" { moved[phase] += $4 }
               END { printf "%d %d %d", moved[0], moved[1], moved[2] }' "$t")
  read -r before during after <<<"$order"
  echo "drag: $presses press(es), $releases release(s); REL_X before $before, held $during, after $after"
  echo "drag: press at $(button_times "$t" 1 | head -1) s, release at $(button_times "$t" 0 | head -1) s"
  check "drag: one press ($presses)" eq "$presses" 1
  check "drag: one release ($releases)" eq "$releases" 1
  check "drag: the cursor moves right while the button is down (REL_X $during >= 400)" ge "$during" 400
  # The hand is still until the push: any motion before the press is noise.
  check "drag: no motion before the press (REL_X $before)" le "$(abs "$before")" 40
}
