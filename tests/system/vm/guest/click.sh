# SPDX-License-Identifier: MIT
# Click (docs/testing.md): the click clip (rightdown's motion with one push toward the camera at
# 6.0-6.7 s) gives exactly one BTN_LEFT press and one release, the press during the push; the
# rightdown clip, the same motion without the push, gives no button event at all.
scenario() {
  load_modules
  camera=/dev/video0
  write_config "$work/relative.ini" relative
  run_clip click "$work/relative.ini" click
  local presses releases press release
  presses=$(count "$work/events-click.txt" 'BTN_LEFT 1$')
  releases=$(count "$work/events-click.txt" 'BTN_LEFT 0$')
  press=$(button_times "$work/events-click.txt" 1 | head -1)
  release=$(button_times "$work/events-click.txt" 0 | head -1)
  echo "click: $presses press(es) (first at ${press:-none} s), $releases release(s) (first at ${release:-none} s)"
  check "click: exactly one press ($presses)" eq "$presses" 1
  check "click: exactly one release ($releases)" eq "$releases" 1
  # The push is 6.0-6.7 s within the stop (5.5-7.5 s); events may come up to 0.6 s late.
  check "click: the press during the push, 6.0-7.3 s (${press:-none})" within "$press" 6.0 7.3
  check "click: the release after it, by 8.0 s (${release:-none})" within "$release" "${press:-99}" 8.0

  camera=/dev/video1
  write_config "$work/relative.ini" relative
  run_clip rightdown "$work/relative.ini" rightdown
  local keys moved
  keys=$(count "$work/events-rightdown.txt" ' EV_KEY ')
  moved=$(sum "$work/events-rightdown.txt" REL_X 0 12)
  check "no push: no button event ($keys)" eq "$keys" 0
  check "no push: it did track (REL_X $moved >= 600)" ge "$moved" 600
}
