// SPDX-License-Identifier: MIT
#include "raypoint/core/click_machine.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {

std::string_view to_string(ClickState state) noexcept {
    switch (state) {
        case ClickState::inactive:
            return "inactive";
        case ClickState::idle:
            return "idle";
        case ClickState::rising:
            return "rising";
        case ClickState::drifting:
            return "drifting";
        case ClickState::pressed:
            return "pressed";
        case ClickState::dragging:
            return "dragging";
        case ClickState::refractory:
            return "refractory";
    }
    return "?";
}

ClickMachine::ClickMachine(const ClickSettings& settings) noexcept : settings_(settings) {}

bool ClickMachine::release_all() noexcept {
    const bool down = state_ == ClickState::pressed || state_ == ClickState::dragging;
    state_ = ClickState::inactive;
    held_since_.reset();
    return down;
}

ClickStep ClickMachine::step(Timestamp timestamp, std::optional<double> scale,
                             bool ready) noexcept {
    now_ = timestamp;
    result_ = ClickStep{};
    if (!scale || !(*scale > 0.0) || !ready) {
        // Whatever the state, the button comes up: nothing may stay pressed without a target
        // the user can see being tracked.
        result_.release = release_all();
    }
    if (!scale || !(*scale > 0.0)) {
        baseline_ = 0.0;
        rise_ = 0.0;
        result_.state = state_;
        return result_;
    }
    scale_ = *scale;
    ready_ = ready;
    // Against the baseline before this frame: a frame never dilutes its own rise.
    rise_ = baseline_ > 0.0 ? scale_ / baseline_ - 1.0 : 0.0;
    switch (state_) {
        case ClickState::inactive:
            on_inactive();
            break;
        case ClickState::idle:
            on_idle();
            break;
        case ClickState::rising:
            on_rising();
            break;
        case ClickState::drifting:
            on_drifting();
            break;
        case ClickState::pressed:
            on_pressed();
            break;
        case ClickState::dragging:
            on_dragging();
            break;
        case ClickState::refractory:
            on_refractory();
            break;
    }
    last_frame_ = now_;
    result_.state = state_;
    return result_;
}

double ClickMachine::seconds_since(Timestamp then) const noexcept {
    // Dividing by 1e6 (exact) rounds correctly, so 800,000 us equals a setting of 0.8 s;
    // multiplying by 1e-6 (inexact) gives 0.7999999999999999 and misses the boundary.
    return static_cast<double>(now_ - then) / 1e6;
}

void ClickMachine::follow_baseline() noexcept {
    // Exponential average on frame time: the same time constant at 10 or 60 fps.
    const double seconds = seconds_since(last_frame_);
    if (seconds <= 0.0) return;
    const double alpha = settings_.baseline_seconds > 0.0
                             ? 1.0 - std::exp(-seconds / settings_.baseline_seconds)
                             : 1.0;
    baseline_ += alpha * (scale_ - baseline_);
}

bool ClickMachine::held(bool condition) noexcept {
    if (!condition) {
        held_since_.reset();
        return false;
    }
    if (!held_since_) held_since_ = now_;
    return seconds_since(*held_since_) >= settings_.press_hold_seconds;
}

void ClickMachine::release() noexcept {
    state_ = ClickState::refractory;
    released_at_ = now_;
    result_.release = true;
    held_since_.reset();
}

bool ClickMachine::pulled_back() noexcept {
    peak_ = std::max(peak_, scale_);
    const bool dropped =
        settings_.release_drop > 0.0 && scale_ <= peak_ * (1.0 - settings_.release_drop);
    return held(rise_ <= settings_.release_rise || dropped);
}

void ClickMachine::on_inactive() noexcept {
    // The baseline is wherever the target is until clicks are allowed: a target that entered
    // the view growing starts from its size at that moment, not from a stale average.
    baseline_ = scale_;
    rise_ = 0.0;
    if (ready_) state_ = ClickState::idle;
}

void ClickMachine::on_idle() noexcept {
    if (rise_ > settings_.start_rise) {
        push_began_ = last_frame_;
        held_since_.reset();
        state_ = ClickState::rising;
        on_rising();  // a low frame rate may bring the whole push in one frame
        return;
    }
    follow_baseline();
}

void ClickMachine::on_rising() noexcept {
    const bool in_time = seconds_since(push_began_) <= settings_.push_seconds;
    // The rise must reach press_rise within push_seconds; holding it there may take longer.
    const bool high = rise_ >= settings_.press_rise && (in_time || held_since_);
    if (rise_ <= settings_.start_rise) {
        state_ = ClickState::idle;
        held_since_.reset();
        follow_baseline();
    } else if (held(high)) {
        state_ = ClickState::pressed;
        pressed_at_ = now_;
        result_.press = true;
        result_.push_began = push_began_;
        held_since_.reset();
        peak_ = scale_;
    } else if (!in_time && !high) {
        state_ = ClickState::drifting;
        follow_baseline();
    }
}

void ClickMachine::on_drifting() noexcept {
    if (rise_ <= settings_.start_rise) state_ = ClickState::idle;
    follow_baseline();
}

void ClickMachine::on_pressed() noexcept {
    if (pulled_back()) {
        release();
    } else if (seconds_since(pressed_at_) >= settings_.drag_seconds) {
        state_ = ClickState::dragging;
    }
}

void ClickMachine::on_dragging() noexcept {
    if (pulled_back()) release();
}

void ClickMachine::on_refractory() noexcept {
    if (seconds_since(released_at_) >= settings_.refractory_seconds &&
        rise_ <= settings_.start_rise) {
        state_ = ClickState::idle;
    }
    follow_baseline();
}

}  // namespace raypoint::core
