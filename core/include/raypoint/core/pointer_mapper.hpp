// SPDX-License-Identifier: MIT
#pragma once
// Tracked position to cursor motion: relative (gain, dead zone, acceleration, sub-pixel
// remainders) or absolute (an active region of the view onto the device range). Pure: frame
// time only, no allocation, no exceptions.

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

struct Motion {
    int dx = 0;  // relative mode, device pixels
    int dy = 0;
    bool has_absolute = false;  // absolute mode, on every tracked frame not held
    int abs_x = 0;
    int abs_y = 0;
};

class PointerMapper {
  public:
    // frame_aspect: the camera frame's width / height; it converts y fractions to frame widths.
    PointerMapper(const MotionSettings& settings, double frame_aspect) noexcept;

    // `position`: the tracker's smoothed x, y (fractions of the frame). With `tracking` false
    // nothing moves and the reference is forgotten, so a new target does not jump the cursor.
    // With `hold` the position is followed but nothing is emitted and remainders are dropped.
    Motion update(Timestamp timestamp, bool tracking, cv::Point2d position, bool hold) noexcept;

    // Forgets the reference position and the remainders (pause, loss of the target).
    void reset() noexcept;

    // The device coordinates of a position in absolute mode (mirrored, active region, clamped).
    cv::Point absolute(cv::Point2d position) const noexcept;

  private:
    Motion relative(Timestamp timestamp, cv::Point2d view, bool hold) noexcept;

    MotionSettings settings_;
    double frame_aspect_;
    bool has_reference_ = false;
    cv::Point2d reference_;  // mirrored x, y in frame widths
    Timestamp reference_time_ = 0;
    cv::Point2d remainder_;  // device pixels not emitted yet, |each| < 1
};

}  // namespace raypoint::core
