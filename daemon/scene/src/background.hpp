// SPDX-License-Identifier: MIT
#pragma once
// The static scene behind the target, as the lens forms it (before vignetting, exposure gain
// and sensor noise). Procedural and deterministic from the seed: no file is read, but for a
// photograph the spec names.

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace raypoint::scene {

// CV_32FC3, BGR grey levels 0..255 at full light.
cv::Mat make_plain_board(cv::Size size, std::uint64_t seed);
cv::Mat make_room(cv::Size size, std::uint64_t seed);
cv::Mat make_skin_wall(cv::Size size, std::uint64_t seed);  // surfaces.cpp
cv::Mat make_desk(cv::Size size, std::uint64_t seed);
// Throws std::invalid_argument when `path` cannot be read as an image.
cv::Mat make_photo(cv::Size size, const std::string& path, std::uint64_t seed);  // photo.cpp

}  // namespace raypoint::scene
