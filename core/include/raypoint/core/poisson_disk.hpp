// SPDX-License-Identifier: MIT
#pragma once
// The Poisson-disk filter's taps (paper 4.1, "a Poisson-disk filter of radius 5").

#include <vector>

#include <opencv2/core.hpp>

namespace raypoint::core {

// The Poisson-disk filter's tap count: a power of two, so the taps' mean is a shift.
inline constexpr int poisson_disk_tap_count = 16;

// Offsets of the Poisson-disk filter's taps in a unit disk: a fixed, deterministic sample set
// (best-candidate sampling, minimum spacing about 0.45 radius) including the centre.
const std::vector<cv::Point2f>& poisson_disk_taps();

}  // namespace raypoint::core
