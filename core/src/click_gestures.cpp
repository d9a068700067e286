// SPDX-License-Identifier: MIT
// The click machine's gestures after a press: a push held still (HOLDING, RIGHT_ARMED) becomes a
// right click, a push held while moving becomes a drag or a scroll (click_machine.hpp;
// docs/pointer.md, "Right click, double click and scroll").
#include <algorithm>
#include <cmath>

#include "raypoint/core/click_machine.hpp"

namespace raypoint::core {

void ClickMachine::on_holding() noexcept {
    if (pulled_back()) {
        press_left();  // a click: press and release in one command
        release();
        return;
    }
    if (moved_while_held()) return;
    follow_stillness();
    if (settings_.right_seconds > 0.0) {
        // Back at a size it jumped away from, the target stays there a while first: a push
        // coming back passes the sizes it went through on its way in in a frame or two.
        if (seconds_since(still_since_) >= settings_.right_seconds &&
            seconds_since(level_since_) >= 2.0 * settings_.hold_flicker_seconds)
            state_ = ClickState::right_armed;
    } else if (seconds_since(pressed_at_) >= settings_.drag_seconds) {
        // Scroll alone: holding still drags, as without it.
        state_ = ClickState::dragging;
        press_left();
    }
}

void ClickMachine::follow_stillness() noexcept {
    // Still in size too: a slow push still growing, or one that already comes back, is not a
    // held push. The size is the peak of the last hold_flicker_seconds: a region that drops a
    // piece for a frame is as still as its hand.
    if (scale_ >= peak_held_ || seconds_since(peak_held_at_) > settings_.hold_flicker_seconds) {
        peak_held_ = scale_;
        peak_held_at_ = now_;
    }
    // A jump: more than hold_rise from the frame before, per 1/30 s between them (a quick push
    // at 10 fps grows 10-25% a frame). A step: more than hold_rise, whatever the interval; only
    // a step comes back to a size the region crept from (at 10 fps its 5% snap is no jump).
    const double frames = std::max(1.0, seconds_since(last_frame_) * 30.0);
    const double change = last_scale_ > 0.0 ? std::abs(scale_ / last_scale_ - 1.0) : 0.0;
    if (change > settings_.hold_rise * frames) jumped_at_ = now_;
    if (change > settings_.hold_rise) stepped_at_ = now_;
    if (std::abs(peak_held_ / still_scale_ - 1.0) <= settings_.hold_rise) return;
    // A region that takes in a piece for a few frames and drops it again (or drops one and
    // takes it back) changes shape, not depth: back at the size it jumped away from, the target
    // has been still since it was still there. A push comes closer and goes back gradually, so
    // a size it moved away from without a jump is one to come back to only by a step: a region
    // that creeps into a piece over half a second and drops it in one frame (5-6% of sqrt(area)
    // on the gesture set's held hands) changed shape too.
    const bool jumped = seconds_since(jumped_at_) <= settings_.hold_flicker_seconds;
    const bool stepped = seconds_since(stepped_at_) <= settings_.hold_flicker_seconds;
    const bool back = other_scale_ > 0.0 && (!other_crept_ || stepped) &&
                      std::abs(peak_held_ / other_scale_ - 1.0) <= settings_.hold_rise;
    const Timestamp left_since = still_since_;
    if (back) {
        still_since_ = std::min(left_since, other_since_);
        other_since_ = still_since_;
    } else {
        other_since_ = left_since;
        still_since_ = now_;
    }
    other_crept_ = !jumped && !back;
    other_scale_ = still_scale_;
    still_scale_ = peak_held_;
    level_since_ = now_;
}

bool ClickMachine::moved_while_held() noexcept {
    // A step the depth signal took out moved the centroid with the region, and the smoothed
    // position follows it for several frames: the hold counts from where that left it.
    if (within_step(settings_.hold_settle_seconds)) {
        held_at_ = where_;
        held_step_offset_ = step_offset_;
    }
    // At 10 fps a step the depth signal left in, as a push's possible growth, moved it too: a
    // held push does not grow by glitch_step in a frame, so the region did.
    const cv::Point2d moved = where_ - held_at_ - (step_offset_ - held_step_offset_);
    if (cv::norm(moved) <= settings_.hold_radius) return false;
    // Once the size is half of release_drop under the held size, the push is on its way back
    // (pulled_back() takes it at once from there where the target's own size is home): a
    // region that changes shape as the hand comes back moves the centroid, not the hand.
    if (settings_.release_drop > 0.0 && scale_ < peak_held_ * (1.0 - settings_.release_drop / 2.0))
        return false;
    if (settings_.scroll_gain > 0.0 && std::abs(moved.y) > std::abs(moved.x)) {
        state_ = ClickState::scrolling;
        result_.scroll = -moved.y;  // y grows downward; up scrolls up
        scroll_y_ = where_.y;
    } else {
        state_ = ClickState::dragging;
        press_left();
    }
    return true;
}

void ClickMachine::on_right_armed() noexcept {
    // The right click comes whole at the pull-back, not when the stillness was reached: a
    // drag whose hand rests before it moves is still a drag.
    if (pulled_back()) {
        result_.right_press = true;
        result_.right_release = true;
        release();
        return;
    }
    moved_while_held();
}

void ClickMachine::on_scrolling() noexcept {
    if (pulled_back()) {
        release();
        return;
    }
    result_.scroll = scroll_y_ - where_.y;
    scroll_y_ = where_.y;
}

}  // namespace raypoint::core
