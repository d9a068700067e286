// SPDX-License-Identifier: MIT
#include "raypoint/core/pointer_mapper.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {
namespace {

// REL_X / REL_Y values are 32-bit; this is far beyond any hand's speed and keeps the cast safe.
constexpr double max_step = 1e6;

// Whole pixels of `wanted`, truncated toward zero. Fractions of the frame are inexact in binary
// (0.6 - 0.5 = 0.09999999999999998), so a step of exactly 100 px would come out as 99 with a
// remainder of 0.99999999999998; the snap rounds such steps to the pixel they mean.
double whole_pixels(double wanted) noexcept {
    constexpr double snap = 1e-9;
    return std::clamp(std::trunc(wanted + std::copysign(snap, wanted)), -max_step, max_step);
}

// One axis of the active region onto 0..1; an empty region means the whole frame.
double normalise(double value, double low, double high) noexcept {
    if (!(high > low)) {
        low = 0.0;
        high = 1.0;
    }
    return std::clamp((value - low) / (high - low), 0.0, 1.0);
}

}  // namespace

PointerMapper::PointerMapper(const MotionSettings& settings, double frame_aspect) noexcept
    : settings_(settings), frame_aspect_(frame_aspect > 0.0 ? frame_aspect : 4.0 / 3.0) {}

void PointerMapper::reset() noexcept {
    has_reference_ = false;
    remainder_ = {};
}

cv::Point PointerMapper::absolute(cv::Point2d position) const noexcept {
    const double x = settings_.mirror ? 1.0 - position.x : position.x;
    const double u = normalise(x, settings_.active_left, settings_.active_right);
    const double v = normalise(position.y, settings_.active_top, settings_.active_bottom);
    const double range = static_cast<double>(std::max(settings_.absolute_max, 1));
    return {static_cast<int>(std::lround(u * range)), static_cast<int>(std::lround(v * range))};
}

Motion PointerMapper::update(Timestamp timestamp, bool tracking, cv::Point2d position,
                             bool hold) noexcept {
    if (!tracking) {
        reset();
        return {};
    }
    switch (settings_.mode) {
        case PointerMode::relative: {
            // Frame widths on both axes, x as the user sees it.
            const cv::Point2d view(settings_.mirror ? 1.0 - position.x : position.x,
                                   position.y / frame_aspect_);
            return relative(timestamp, view, hold);
        }
        case PointerMode::absolute: {
            if (hold) return {};
            const cv::Point device = absolute(position);
            return Motion{0, 0, true, device.x, device.y};
        }
    }
    return {};
}

Motion PointerMapper::relative(Timestamp timestamp, cv::Point2d view, bool hold) noexcept {
    if (!has_reference_) {
        has_reference_ = true;
        reference_ = view;
        reference_time_ = timestamp;
        return {};
    }
    const double seconds = static_cast<double>(timestamp - reference_time_) / 1e6;
    if (seconds <= 0.0) return {};  // a repeated timestamp: no speed to measure
    const cv::Point2d delta = view - reference_;
    reference_ = view;
    reference_time_ = timestamp;
    if (hold) {
        remainder_ = {};
        return {};
    }
    const double speed = std::hypot(delta.x, delta.y) / seconds;  // frame widths per second
    const double over = speed - std::max(settings_.dead_zone, 0.0);
    if (over <= 0.0) return {};
    // Shrinking the step by the dead zone's share keeps the output continuous at its edge.
    const double scale =
        settings_.gain * (over / speed) * (1.0 + std::max(settings_.acceleration, 0.0) * over);
    const cv::Point2d wanted = delta * scale + remainder_;
    // Truncation toward zero keeps |remainder| < 1 with the sign of the motion, so a slow hand
    // gets every pixel it travelled, just later, and a stop leaves no phantom pixel behind.
    const cv::Point2d emitted(whole_pixels(wanted.x), whole_pixels(wanted.y));
    remainder_ = wanted - emitted;
    if (std::abs(remainder_.x) >= 1.0) remainder_.x = 0.0;  // only after a clamped step
    if (std::abs(remainder_.y) >= 1.0) remainder_.y = 0.0;
    return Motion{static_cast<int>(emitted.x), static_cast<int>(emitted.y), false, 0, 0};
}

}  // namespace raypoint::core
