// SPDX-License-Identifier: MIT
// Motion blur as the renderer draws it: what moves during the exposure is drawn at evenly spaced
// sub-positions and averaged, for the target and for an object passing behind it alike.
#pragma once

#include <algorithm>
#include <cmath>

namespace raypoint::scene {

// Sub-position spacing, pixels: larger steps show as ghost edges.
inline constexpr double blur_step_px = 2.0;
inline constexpr int max_sub_frames = 12;

// How many sub-positions cover a travel of `travel_px` pixels during the exposure.
inline int sub_frame_count(double travel_px) {
    const double steps = std::ceil(travel_px / blur_step_px);
    return std::clamp(static_cast<int>(steps) + 1, 1, max_sub_frames);
}

}  // namespace raypoint::scene
