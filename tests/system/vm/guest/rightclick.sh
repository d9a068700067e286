# SPDX-License-Identifier: MIT
# Right click (docs/pointer.md): the rightclick clip (a push at 5.5 s held still until 7.1 s)
# with the gestures on gives one BTN_RIGHT press and its release at the pull-back (the push
# was still for 0.6 s, so the pull-back right-clicks), and no BTN_LEFT at all.
scenario() {
  load_modules
  write_gesture_config "$work/gestures.ini"
  run_clip rightclick "$work/gestures.ini" rightclick
  local t="$work/events-rightclick.txt" presses releases lefts press release
  presses=$(count "$t" 'BTN_RIGHT 1$')
  releases=$(count "$t" 'BTN_RIGHT 0$')
  lefts=$(count "$t" ' BTN_LEFT ')
  press=$(key_times "$t" BTN_RIGHT 1 | head -1)
  release=$(key_times "$t" BTN_RIGHT 0 | head -1)
  echo "rightclick: $presses right press(es) (first at ${press:-none} s), $releases release(s) (first at ${release:-none} s), $lefts left event(s)"
  check "rightclick: one right press ($presses)" eq "$presses" 1
  check "rightclick: one right release ($releases)" eq "$releases" 1
  check "rightclick: no left button ($lefts)" eq "$lefts" 0
  # Pushed in by 5.7 s, still for 0.6 s by 6.3 s, pulled back from 7.1 s: 7.30 s (the host's
  # figure); events may come up to 0.6 s late.
  check "rightclick: the press at the pull-back, 7.1-7.9 s (${press:-none})" within "$press" 7.1 7.9
  check "rightclick: the release after it, by 8.5 s (${release:-none})" within "$release" "${press:-99}" 8.5
}
