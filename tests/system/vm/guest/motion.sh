# SPDX-License-Identifier: MIT
# Motion (docs/testing.md): the rightdown clip (the hand moves right 4.0-5.5 s, stands, moves
# down 7.5-9.0 s, stands) through raypoint run, in both pointer modes: the cursor's events move
# right, then down. The stretches are read from 3.9 s to 7.4 s and from 7.4 s to the end.
scenario() {
  load_modules
  for mode in relative absolute; do
    [ "$mode" = relative ] && camera=/dev/video0 || camera=/dev/video1
    write_config "$work/$mode.ini" "$mode"
    start_writer rightdown "writer-$mode.log" --wait
    start_recorder "events-$mode.txt"
    start_daemon "$work/$mode.ini" "$mode"
    wait_ready
    go
    wait "$writer_pid"
    sleep 0.5
    stop "$daemon_pid" "$recorder_pid" "$listener_pid"
    "motion_$mode" "$work/events-$mode.txt"
  done
}

# Sums of REL_X and REL_Y a stretch: at least half the host's figure (1211 right, 724 down;
# gain 2400 px a frame width with acceleration), the other axis within 10% of it.
motion_relative() {
  local right_x right_y down_x down_y
  right_x=$(sum "$1" REL_X 3.9 7.4)
  right_y=$(sum "$1" REL_Y 3.9 7.4)
  down_x=$(sum "$1" REL_X 7.4 12)
  down_y=$(sum "$1" REL_Y 7.4 12)
  echo "relative: right stretch REL_X $right_x REL_Y $right_y; down stretch REL_X $down_x REL_Y $down_y"
  check "relative: moves right (REL_X $right_x >= 600)" ge "$right_x" 600
  check "relative: not down or up while moving right (|REL_Y| $(abs "$right_y") <= REL_X / 10)" \
    le "$(abs "$right_y")" $((right_x / 10))
  check "relative: then moves down (REL_Y $down_y >= 360)" ge "$down_y" 360
  check "relative: not sideways while moving down (|REL_X| $(abs "$down_x") <= REL_Y / 10)" \
    le "$(abs "$down_x")" $((down_y / 10))
}

# ABS_X, ABS_Y before, between and after the stretches: the active region (0.1-0.9 of the
# frame) spans 0..65535, so 0.4 of the width right is 32767 and 0.35 of the height down 28672;
# within 25% of that, the other axis within 5% of the range (3277).
motion_absolute() {
  local x0 y0 x1 y1 x2 y2
  x0=$(value_at "$1" ABS_X 3.9)
  y0=$(value_at "$1" ABS_Y 3.9)
  x1=$(value_at "$1" ABS_X 7.4)
  y1=$(value_at "$1" ABS_Y 7.4)
  x2=$(value_at "$1" ABS_X 12)
  y2=$(value_at "$1" ABS_Y 12)
  echo "absolute: ($x0, $y0) at 3.9 s, ($x1, $y1) at 7.4 s, ($x2, $y2) at the end"
  if [ -z "$x0" ] || [ -z "$y0" ] || [ -z "$x1" ] || [ -z "$y1" ] || [ -z "$x2" ] || [ -z "$y2" ]; then
    bad "absolute: no position at one of 3.9 s, 7.4 s, the end"
    return
  fi
  local right=$((x1 - x0)) down=$((y2 - y1))
  check "absolute: moves right (ABS_X +$right within 24575..40959)" \
    eval "ge $right 24575 && le $right 40959"
  check "absolute: level while moving right (ABS_Y $((y1 - y0)))" le "$(abs $((y1 - y0)))" 3277
  check "absolute: then moves down (ABS_Y +$down within 21504..35840)" \
    eval "ge $down 21504 && le $down 35840"
  check "absolute: straight down (ABS_X $((x2 - x1)))" le "$(abs $((x2 - x1)))" 3277
}
