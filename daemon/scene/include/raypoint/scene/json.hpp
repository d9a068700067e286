// SPDX-License-Identifier: MIT
#pragma once
// The text formats of a scene folder, the same as the dev scenes' (truth.jsonl, scene.json).

#include <string>

#include "raypoint/scene/scene_spec.hpp"
#include "raypoint/scene/truth.hpp"

namespace raypoint::scene {

// One truth.jsonl line without the newline: frame, t, present and, when present, moving,
// centroid [x, y], area, bbox [x, y, w, h] and depth. Numbers are rounded to 6 (bbox and
// depth: 5) decimals.
std::string truth_json(const Truth& truth);

// scene.json: the spec's conditions plus the frame count.
std::string scene_json(const SceneSpec& spec, int frames);

}  // namespace raypoint::scene
