# SPDX-License-Identifier: MIT
# Scroll (docs/pointer.md): the scroll clip (a push at 5.5 s held while the hand moves up by a
# quarter of the frame's height, 5.8-7.3 s) with the gestures on turns the wheel up: REL_WHEEL
# and REL_WHEEL_HI_RES both positive, the hi-res sum 120 a detent, and no button at all. The
# host measures 7 detents (869 in 120ths).
scenario() {
  load_modules
  write_gesture_config "$work/gestures.ini"
  run_clip scroll "$work/gestures.ini" scroll
  local t="$work/events-scroll.txt" wheel hires keys down
  wheel=$(sum "$t" REL_WHEEL 0 20)
  hires=$(sum "$t" REL_WHEEL_HI_RES 0 20)
  keys=$(count "$t" ' EV_KEY ')
  down=$(awk '$3 == "REL_WHEEL" && $4 < 0' "$t" | wc -l)
  echo "scroll: REL_WHEEL $wheel, REL_WHEEL_HI_RES $hires, $keys key event(s), $down downward step(s)"
  check "scroll: the wheel turned up at least 4 detents ($wheel)" ge "$wheel" 4
  check "scroll: hi-res follows, 120 a detent ($hires vs $wheel)" \
    within "$hires" "$((wheel * 120))" "$((wheel * 120 + 119))"
  check "scroll: no button ($keys)" eq "$keys" 0
}
