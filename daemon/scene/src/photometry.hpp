// SPDX-License-Identifier: MIT
#pragma once
// How light reaches the sensor and what the sensor adds: vignetting, the exposure gain over
// time, and Gaussian noise.

#include <cstdint>

#include <opencv2/core.hpp>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

// CV_32F relative illumination: 1 at the centre, 0.85 in the corners (cos^4-like falloff of a
// cheap wide lens, kept slight).
cv::Mat make_vignette(cv::Size size);

// Multiplier on the scene's grey levels at time t: darkness times the auto-exposure level,
// which each brightness jump toggles between 1 and 1 / (1 + brightness_jump).
double exposure_gain(const SceneSpec& spec, double t);

// Per-channel (B, G, R) multipliers at time t from the slow exposure and white-balance drift.
cv::Vec3d drift_gains(const SceneSpec& spec, double t);

// Multiplier of row y (of `rows`) of the frame exposed at time t from mains flicker.
double flicker_gain(const SceneSpec& spec, double t, int y, int rows);

// Sensor noise for every frame cut from one pre-drawn field at per-frame offsets: drawing
// 640x480x3 Gaussian numbers a frame would cost more than the rest of the rendering. Two
// frames never share an offset with their neighbour, so frame differences stay pure noise.
class NoisePool {
  public:
    NoisePool(cv::Size size, double sigma, std::uint64_t seed);
    bool empty() const { return field_.empty(); }
    // CV_32FC3, size of the frame, grey levels.
    cv::Mat frame_noise(int index) const;

  private:
    cv::Point offset(int index) const;

    cv::Size size_;
    std::uint64_t seed_;
    cv::Mat field_;  // frame size plus `slack` each way
};

}  // namespace raypoint::scene
