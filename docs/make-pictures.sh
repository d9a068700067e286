#!/bin/bash
# SPDX-License-Identifier: MIT
# Regenerates every picture in docs/pictures/ from scenes rendered on the spot, with raypoint's
# own commands (preview --headless, track --plot). usage: docs/make-pictures.sh [BUILD_DIR]
# (or `cmake --build build --target docs-pictures`). Screenshots are JPEG (a rendered camera
# picture's noise does not compress as PNG), plots PNG; each a few tens of kB.
set -eu
build=$(cd "${1:-build}" && pwd)
raypoint=$build/raypoint
render=$build/tests/scene/raypoint-render-scene
out=$(cd "$(dirname "$0")" && pwd)/pictures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
# No user configuration: the pictures show the defaults and the settings named here.
export XDG_CONFIG_HOME="$work/config" XDG_CONFIG_DIRS="$work/none" XDG_RUNTIME_DIR="$work"

for scene in realworld interfering push fast; do
  "$render" --preset "$scene" --out "$work/$scene" --no-masks > /dev/null
done

# preview SCENE FRAMES NAME [raypoint options...]: the picture after FRAMES frames.
preview() {
  local scene=$1 frames=$2 name=$3
  shift 3
  "$raypoint" preview --input "$work/$scene/video.mp4" --headless --frames "$frames" \
    --screenshot "$out/$name.jpg" --no-control "$@" > /dev/null
}
# plot SCENE NAME [raypoint options...]: x, y, z, the state and the clicks over the clip.
plot() {
  local scene=$1 name=$2
  shift 2
  "$raypoint" track "$work/$scene/video.mp4" --plot "$out/$name.png" "$@" > /dev/null
}

# Edge threshold, frame 140 of the skin hand in a busy room: the default 96 closes the hand's
# outline; at 160 its edges against the wall fade, and the rays leak into the sofa.
preview realworld 141 edge-threshold-96
preview realworld 141 edge-threshold-160 --set preprocess.edge_threshold=160
# Difference image: what picks the target and measures movement (the hand moving).
preview realworld 125 difference-view --view difference
# Area window: the sphere over a busy room grows to 9.6% of the frame as it comes closer;
# max_area 0.06 drops it again and again (too-large), the default 0.60 keeps it.
plot interfering area-window-default
plot interfering max-area-0.06 --set tracking.max_area=0.06
# Press threshold: the push scene's two pushes peak at a rise of 0.35.
plot push press-rise-default
plot push press-rise-0.40 --set click.press_rise=0.40
# A recovery: RECOVERING's 16 points around the failed inner point (frame 44 of the fast
# scene), and the whole clip's state band.
preview fast 45 recovering
plot fast fast-losses
ls -l "$out"
