// SPDX-License-Identifier: MIT
#pragma once
// Smoothing of the 3D output (paper 4.3) and the One Euro alternative (Casiez et al. 2012).

#include <array>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::core {

// One Euro filter for one value on frame time: a low-pass whose cutoff rises with speed, so a
// still hand is steady and a fast one does not lag.
class OneEuroFilter {
  public:
    OneEuroFilter(double min_cutoff_hz, double beta, double derivative_cutoff_hz) noexcept;
    void reset(double value, Timestamp timestamp) noexcept;
    double update(double value, Timestamp timestamp) noexcept;

  private:
    double min_cutoff_;
    double beta_;
    double derivative_cutoff_;
    double value_ = 0.0;
    double derivative_ = 0.0;
    Timestamp last_ = 0;
};

// The EMA's weight of the old value for a frame `seconds` after the last (OutputSettings::
// ema_frame_rate): ema_weight once a frame at rate 0, on a first frame (seconds <= 0), and for
// frames closer than 1/rate s.
double ema_weight_after(const OutputSettings& settings, double seconds) noexcept;

class PositionSmoother {
  public:
    explicit PositionSmoother(const OutputSettings& settings) noexcept;
    // Starts over at `position` (a new target: no lag from the previous one).
    void reset(cv::Point3d position, Timestamp timestamp) noexcept;
    cv::Point3d update(cv::Point3d position, Timestamp timestamp) noexcept;

  private:
    OutputSettings settings_;
    cv::Point3d smoothed_;
    Timestamp last_ = 0;
    bool has_last_ = false;
    std::array<OneEuroFilter, 3> one_euro_;
};

}  // namespace raypoint::core
