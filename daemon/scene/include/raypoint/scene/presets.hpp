// SPDX-License-Identifier: MIT
#pragma once
// Named scenes mirroring the paper's experiments (section 5) and the dev scenes:
//   ideal        sphere, white board, 30 fps
//   lowlight     sphere, white board, 10 fps, dark, heavy noise, strong blur
//   interfering  sphere over a cluttered room
//   nonconvex    blue paper hand, white board, 30 fps
//   realworld    skin hand, cluttered room
//   hd60         skin hand, cluttered room, 60 fps
//   exposure     sphere, white board, six brightness jumps (two before the target enters)
//   jpeg         sphere, cluttered room, JPEG quality 35
//   fast         paper hand, 15 fps, 2.4x speed, exposure over the whole frame interval
//   pause        skin hand in a cluttered room that holds still for 3.5 s mid-clip (10 s)
//   push         paper hand that moves, holds, and pushes toward the camera twice (9 s)
//   person       skin hand in front of a person (face, neck, shirt) who breathes and turns
//   skinwall     skin hand against a warm beige or pink wall
//   desk         skin hand over a wooden desk seen from above
//   sleeve       skin hand on a forearm in a sleeve of nearly its colour (truth: the hand)
//   passer       realworld with a dark ball crossing behind the hand every 2.5 s (10 s)

#include <string>
#include <string_view>
#include <vector>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

// Throws std::invalid_argument naming the preset and listing the valid ones.
SceneSpec preset(std::string_view name);

std::vector<std::string_view> preset_names();

}  // namespace raypoint::scene
