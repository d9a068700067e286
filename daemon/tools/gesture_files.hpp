// SPDX-License-Identifier: MIT
#pragma once
// eval-clicks' files: the photographs a folder holds, and the gesture set written as videos with
// their truth.

#include <string>
#include <vector>

#include "raypoint/scene/gesture_set.hpp"

namespace raypoint::daemon {

// The JPEG and PNG files in `dir`, sorted, so that a seed draws the same ones each time. Throws
// InputError when the folder cannot be listed or holds none.
std::vector<std::string> photos_in(const std::string& dir);

// Each clip of `set` (only the one named `only`, when given) as DIR/NAME.mp4 with its truth in
// DIR/NAME.mp4.clicks. Throws InputError when a file cannot be written.
void write_set(const std::vector<scene::GestureClip>& set, const std::string& dir,
               const std::string& only);

}  // namespace raypoint::daemon
