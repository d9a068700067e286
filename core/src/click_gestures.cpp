// SPDX-License-Identifier: MIT
// The click machine's gestures after a press: a push held still (HOLDING, RIGHT_ARMED) becomes a
// right click, a push held while moving becomes a drag or a scroll (click_machine.hpp;
// docs/pointer.md, "Right click, double click and scroll").
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
    // Still in size too: a slow push still growing, or one that already comes back, is not a
    // held push. The size is the peak of the last hold_flicker_seconds: a region that drops a
    // piece for a frame is as still as its hand.
    if (scale_ >= peak_held_ || seconds_since(peak_held_at_) > settings_.hold_flicker_seconds) {
        peak_held_ = scale_;
        peak_held_at_ = now_;
    }
    if (std::abs(peak_held_ / still_scale_ - 1.0) > settings_.hold_rise) {
        still_scale_ = peak_held_;
        still_since_ = now_;
    }
    if (settings_.right_seconds > 0.0) {
        if (seconds_since(still_since_) >= settings_.right_seconds)
            state_ = ClickState::right_armed;
    } else if (seconds_since(pressed_at_) >= settings_.drag_seconds) {
        // Scroll alone: holding still drags, as without it.
        state_ = ClickState::dragging;
        press_left();
    }
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
