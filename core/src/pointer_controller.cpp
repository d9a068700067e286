// SPDX-License-Identifier: MIT
#include "raypoint/core/pointer_controller.hpp"

#include "raypoint/core/smoothing.hpp"

#include <cmath>

namespace raypoint::core {
namespace {

void put_motion(PointerCommand& command, const Motion& motion) noexcept {
    command.dx = motion.dx;
    command.dy = motion.dy;
    command.has_absolute = motion.has_absolute;
    command.abs_x = motion.abs_x;
    command.abs_y = motion.abs_y;
}

}  // namespace

PointerController::PointerController(const PointerSettings& settings, double frame_aspect,
                                     const OutputSettings& output) noexcept
    : settings_(settings),
      frame_aspect_(frame_aspect > 0.0 ? frame_aspect : 4.0 / 3.0),
      mapper_(settings.motion, frame_aspect_),
      depth_(settings.click),
      clicker_(settings.click),
      dweller_(settings.dwell),
      output_(output) {}

void PointerController::change(PointerCommand& command, Button button, bool pressed) noexcept {
    bool& down = down_[index(button)];
    if (down == pressed) return;  // the device already has it so
    down = pressed;
    command.add(button, pressed);
}

void PointerController::release_down(PointerCommand& command) noexcept {
    for (const Button button : {Button::left, Button::right, Button::middle})
        change(command, button, false);
}

// ClickSettings::push_region_jump: after the depth signal's update for the frame.
void PointerController::follow_region(bool has_target, cv::Point2d centroid, cv::Point2d chained,
                                      Timestamp now) noexcept {
    if (!has_target) {
        region_jumps_ = region_offset_ = last_jump_ = step_jumps_ = step_offset_ = chain_offset_ =
            cv::Point2d();
        has_last_centroid_ = false;
    } else {
        cv::Point2d jump;
        if (has_last_centroid_ && depth_.absorbed()) jump = centroid - last_centroid_;
        // A step given back was the target's after all: its jump counts again.
        if (depth_.given_back()) region_jumps_ -= last_jump_;
        region_jumps_ += jump;
        last_jump_ = jump;
        if (has_last_centroid_ && depth_.stepped() && !depth_.absorbed())
            step_jumps_ += centroid - last_centroid_;
        // As the tracker's smoothing passes the sum on to the position (Tracker::process: linear,
        // so the sum's share of the position is the sum smoothed alike).
        const double seconds =
            has_last_centroid_ ? static_cast<double>(now - last_centroid_at_) * 1e-6 : 0.0;
        const double weight =
            output_.smoothing == SmoothingKind::ema ? ema_weight_after(output_, seconds) : 0.0;
        region_offset_ = region_offset_ * weight + region_jumps_ * (1.0 - weight);
        step_offset_ = step_offset_ * weight + step_jumps_ * (1.0 - weight);
        chain_offset_ = chain_offset_ * weight + chained * (1.0 - weight);
        last_centroid_ = centroid;
        last_centroid_at_ = now;
        has_last_centroid_ = true;
    }
    clicker_.set_region(region_jumps_, region_offset_, step_offset_);
}

PointerCommand PointerController::release_all() noexcept {
    PointerCommand command;
    clicker_.release_all();
    depth_.reset();
    dweller_.reset();
    mapper_.reset();
    tracking_since_.reset();
    follow_region(false, cv::Point2d(), cv::Point2d(), 0);
    undo_ = {};
    before_push_.reset();
    wheel_remainder_ = 0.0;
    release_down(command);
    return command;
}

PointerCommand PointerController::update(const FrameResult& frame) noexcept {
    const Timestamp now = frame.timestamp;
    const bool tracking = frame.state == TrackerState::tracking;
    if (!tracking) {
        tracking_since_.reset();
    } else if (!tracking_since_) {
        tracking_since_ = now;  // the frame that picked the target
    }
    // The frame that picks a target has neither area nor position: it moves and clicks nothing.
    const bool has_target = tracking && frame.has_position && frame.area && *frame.area > 0.0;
    const bool ready = has_target && static_cast<double>(now - *tracking_since_) / 1e6 >=
                                         settings_.safety.min_tracking_seconds;
    const cv::Point2d position(frame.position.x, frame.position.y);

    PointerCommand command;
    switch (settings_.click.mode) {
        case ClickMode::depth: {
            const double raw = has_target ? std::sqrt(*frame.area) : 0.0;
            // Frame widths on both axes, as the hold radius is.
            const cv::Point2d& region = frame.followed ? frame.region_centroid : frame.centroid;
            const cv::Point2d centroid(region.x, region.y / frame_aspect_);
            const cv::Point2d chained =
                frame.followed ? cv::Point2d(frame.centroid.x - region.x,
                                             (frame.centroid.y - region.y) / frame_aspect_)
                               : cv::Point2d();
            const std::optional<double> scale =
                depth_.update(has_target ? std::optional<double>(raw) : std::nullopt, centroid, now,
                              frame.light_change);
            follow_region(has_target, centroid, chained, now);
            // A push is judged where the region is, as the depth signal reads it: the movement's
            // chain (Tracker, follow_movement) wanders over a growing outline. The cursor goes
            // where the chain is.
            const cv::Point2d where(position.x - chain_offset_.x,
                                    position.y / frame_aspect_ - chain_offset_.y);
            const ClickStep step = clicker_.step(now, scale, ready, where, depth_.given_back(), raw,
                                                 depth_.absorbed(), depth_.jumped());
            // x and y stay where the push began while a button is down or may yet be, and on
            // the frame a held push starts a drag, whose press goes where the push began.
            const bool hold = step.press || step.state == ClickState::pressed ||
                              step.state == ClickState::holding ||
                              step.state == ClickState::right_armed ||
                              step.state == ClickState::scrolling;
            const Motion motion = mapper_.update(now, has_target, position, hold);
            depth_click(step, motion, command);
            break;
        }
        case ClickMode::dwell: {
            const Motion motion = mapper_.update(now, has_target, position, false);
            put_motion(command, motion);
            // Frame widths on both axes, so the radius is a circle on the hand's plane.
            const std::optional<cv::Point2d> where =
                has_target ? std::optional<cv::Point2d>(
                                 cv::Point2d(position.x, position.y / frame_aspect_))
                           : std::nullopt;
            if (dweller_.step(now, where, ready)) {
                change(command, Button::left, true);
                change(command, Button::left, false);
            }
            break;
        }
        case ClickMode::off: {
            const Motion motion = mapper_.update(now, has_target, position, false);
            put_motion(command, motion);
            break;
        }
    }
    if (!has_target) {
        // Nothing stays pressed while the user cannot see it being tracked.
        release_down(command);
        undo_ = {};
        before_push_.reset();
        wheel_remainder_ = 0.0;
    }
    return command;
}

void PointerController::scroll(double up, PointerCommand& command) noexcept {
    // REL_WHEEL_HI_RES counts 120ths of a detent; REL_WHEEL follows each time the sum crosses
    // a whole detent, as a high-resolution mouse wheel reports.
    // Rounded, the rest carried: the sum follows the hand to half a unit.
    const double units = up * settings_.click.scroll_gain * 120.0 + wheel_remainder_;
    const int hi_res = static_cast<int>(std::lround(units));
    wheel_remainder_ = units - hi_res;
    if (hi_res == 0) return;
    const long long detents_before = wheel_hi_res_ / 120;
    wheel_hi_res_ += hi_res;
    command.wheel_hi_res += hi_res;
    command.wheel += static_cast<int>(wheel_hi_res_ / 120 - detents_before);
}

void PointerController::depth_click(const ClickStep& step, const Motion& motion,
                                    PointerCommand& command) noexcept {
    if (step.undo) {
        // The confirming frame's own motion is held; the motion since the push began is
        // undone, so the button goes down where the cursor was when the push started.
        command.dx = -undo_.x;
        command.dy = -undo_.y;
        if (before_push_) {
            command.has_absolute = true;
            command.abs_x = before_push_->x;
            command.abs_y = before_push_->y;
        }
        undo_ = {};
    } else {
        put_motion(command, motion);
        if (step.state == ClickState::rising) {
            undo_ += cv::Point(motion.dx, motion.dy);
        } else {
            // Only idle leads to rising, so the last frame outside it is the one the push
            // began at.
            undo_ = {};
            if (motion.has_absolute) before_push_ = cv::Point(motion.abs_x, motion.abs_y);
        }
    }
    if (step.double_click) {
        change(command, Button::left, true);
        change(command, Button::left, false);
    }
    if (step.press) change(command, Button::left, true);
    if (step.release) change(command, Button::left, false);
    if (step.right_press) change(command, Button::right, true);
    if (step.right_release) change(command, Button::right, false);
    if (step.scroll != 0.0) scroll(step.scroll, command);
    if (step.state != ClickState::scrolling) wheel_remainder_ = 0.0;
}

}  // namespace raypoint::core
