// SPDX-License-Identifier: MIT
#pragma once
// A recorded clip's click truth file (scene/gesture_set.hpp's format): one line a gesture,
// "click|drag|right|double|scroll_up|scroll_down START PRESS RELEASE [DEPTH SECONDS]", and
// "motion FROM TO" for a span of non-push motion, "approach FROM TO" for a span in which the
// target came closer as fast as a push without one being meant (no press there is scored);
// '#' starts a comment.

#include <string>
#include <utility>
#include <vector>

#include "raypoint/scene/gesture_set.hpp"

namespace raypoint::daemon {

struct ClickTruth {
    std::vector<scene::IntendedClick> clicks;             // in the file's order
    std::vector<std::pair<double, double>> motion_spans;  // s
    std::vector<std::pair<double, double>> approaches;    // s
};

// Throws InputError naming the file and line.
ClickTruth read_click_truth(const std::string& truth);

}  // namespace raypoint::daemon
