// SPDX-License-Identifier: MIT
#pragma once
// Draws what the tracker saw on the input frame (--annotate): edges, selected blocks, rays,
// inner point, centroid and state.

#include "raypoint/core/tracker.hpp"

namespace raypoint::daemon {

// Draws onto `frame` (BGR, the input size) in place.
void annotate(cv::Mat& frame, const core::Tracker& tracker, const core::FrameResult& result);

}  // namespace raypoint::daemon
