// SPDX-License-Identifier: MIT
#pragma once
// Truth geometry of a mask that covers only part of the frame.

#include <opencv2/core.hpp>

#include "raypoint/scene/truth.hpp"

namespace raypoint::scene {

// mask: CV_8U, non-zero = target, placed at `offset` in a frame of `frame` size.
Truth measure_mask(const cv::Mat& mask, cv::Point offset, cv::Size frame);

}  // namespace raypoint::scene
