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
        case ClickState::holding:
            return "holding";
        case ClickState::right_armed:
            return "right_armed";
        case ClickState::scrolling:
            return "scrolling";
    }
    return "?";
}

ClickMachine::ClickMachine(const ClickSettings& settings) noexcept : settings_(settings) {}

bool ClickMachine::release_all() noexcept {
    const bool down = state_ == ClickState::pressed || state_ == ClickState::dragging;
    state_ = ClickState::inactive;
    held_since_.reset();
    clicked_at_.reset();
    return down;
}

ClickStep ClickMachine::step(Timestamp timestamp, std::optional<double> scale, bool ready,
                             cv::Point2d where, bool late, double raw, bool absorbed,
                             bool jumped) noexcept {
    now_ = timestamp;
    jumped_ = jumped;
    where_ = where;
    late_ = late;
    // A step given back was the target's own (a push blurred for a frame), not a region change.
    if (late) absorbed_at_.reset();
    if (absorbed) absorbed_at_ = now_;
    result_ = ClickStep{};
    if (!scale || !(*scale > 0.0) || !ready) {
        // Whatever the state, the button comes up: nothing may stay pressed without a target
        // the user can see being tracked.
        result_.release = release_all();
    }
    if (!scale || !(*scale > 0.0)) {
        baseline_ = 0.0;
        rise_ = 0.0;
        last_raw_ = 0.0;
        last_scale_ = 0.0;
        result_.state = state_;
        return result_;
    }
    scale_ = *scale;
    raw_ = raw > 0.0 ? raw : scale_;
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
        case ClickState::holding:
            on_holding();
            break;
        case ClickState::right_armed:
            on_right_armed();
            break;
        case ClickState::scrolling:
            on_scrolling();
            break;
    }
    last_frame_ = now_;
    last_where_ = where_;
    last_region_jumps_ = region_jumps_;
    last_region_offset_ = region_offset_;
    last_raw_ = raw_;
    last_scale_ = scale_;
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

// Linear between the two frames: at 10 fps the rise from start_rise to press_rise of a
// 0.65 s push spans 0.15 s, but its frames fall 0.1 s apart, and counting from the frame before
// the first to the frame after the last stretched it to 0.3 s, past push_seconds.
Timestamp ClickMachine::crossed(double level) const noexcept {
    if (!(last_scale_ > 0.0) || !(baseline_ > 0.0) || now_ <= last_frame_) return now_;
    const double before = last_scale_ / baseline_ - 1.0;
    if (before >= level) return last_frame_;  // there already (the baseline moved since)
    if (rise_ < level) return now_;
    return between_frames((level - before) / (rise_ - before));
}

Timestamp ClickMachine::between_frames(double fraction) const noexcept {
    return last_frame_ + static_cast<Timestamp>(fraction * static_cast<double>(now_ - last_frame_));
}

// At 10 fps the frame that first shows press_rise comes up to 0.1 s after the rise crossed it,
// and counting press_hold_seconds from that frame waited for the next one: 0.1 s of latency for
// a 0.03 s hold. Only for a rise already under way on the previous frame: a single frame that
// jumps from the baseline (a glitch) still has to be held.
Timestamp ClickMachine::press_crossed() const noexcept {
    if (now_ <= rising_at_ || !(baseline_ > 0.0)) return now_;
    if (last_scale_ / baseline_ - 1.0 >= settings_.press_rise) return now_;
    return crossed(settings_.press_rise);
}

bool ClickMachine::held(bool condition, Timestamp since) noexcept {
    if (!condition) {
        held_since_.reset();
        return false;
    }
    if (!held_since_) {
        held_since_ = since;
        // Only the press's hold (RISING): the rise came from under start_rise on this frame.
        held_jump_ = state_ == ClickState::rising && now_ <= rising_at_;
    }
    double hold = held_jump_ ? std::max(settings_.press_hold_seconds, settings_.jump_hold_seconds)
                             : settings_.press_hold_seconds;
    if (state_ == ClickState::rising && travelled_)
        hold = std::max(hold, settings_.travel_hold_seconds);
    return seconds_since(*held_since_) >= hold;
}

void ClickMachine::confirm() noexcept {
    result_.undo = true;
    result_.push_began = push_began_;
    held_since_.reset();
    peak_ = scale_;
    raw_back_since_.reset();
    pressed_at_ = now_;
    if (settings_.right_seconds > 0.0 || settings_.scroll_gain > 0.0) {
        // Which gesture it is shows only after the press: no button until then.
        state_ = ClickState::holding;
        held_at_ = where_;
        held_step_offset_ = step_offset_;
        still_scale_ = scale_;
        still_since_ = now_;
        other_scale_ = 0.0;
        other_crept_ = false;
        other_since_ = now_;
        jumped_at_ = 0;
        stepped_at_ = 0;
        level_since_ = now_;
        peak_held_ = scale_;
        peak_held_at_ = now_;
    } else {
        state_ = ClickState::pressed;
        press_left();
    }
}

void ClickMachine::press_left() noexcept {
    result_.press = true;
    // From the last click's release to this push's beginning: the time the user paused,
    // whatever each push's own duration.
    result_.double_click =
        settings_.double_seconds > 0.0 && clicked_at_ &&
        static_cast<double>(push_began_ - *clicked_at_) / 1e6 <= settings_.double_seconds;
    doubled_ = result_.double_click;
}

bool ClickMachine::within_step(double seconds) const noexcept {
    return absorbed_at_ && seconds > 0.0 && seconds_since(*absorbed_at_) <= seconds;
}

void ClickMachine::on_inactive() noexcept {
    // The baseline is wherever the target is until clicks are allowed: a target that entered
    // the view growing starts from its size at that moment, not from a stale average.
    baseline_ = scale_;
    rise_ = 0.0;
    if (ready_) state_ = ClickState::idle;
}

void ClickMachine::on_idle() noexcept {
    // The region is still changing after a step the depth signal took out: its growth is the
    // region taking in more, not a push. Never down: a flicker's return would be a rise.
    if (within_step(settings_.settle_seconds)) {
        baseline_ = std::max(baseline_, scale_);
        return;
    }
    if (rise_ > settings_.start_rise) {
        push_began_ = crossed(settings_.start_rise);
        rising_at_ = now_;
        push_from_ = last_where_;
        push_region_jumps_ = last_region_jumps_;
        push_region_offset_ = last_region_offset_;
        push_raw_ = last_raw_;
        push_peak_ = 0.0;
        travelled_ = false;
        held_since_.reset();
        state_ = ClickState::rising;
        on_rising();  // a low frame rate may bring the whole push in one frame
        return;
    }
    follow_baseline();
}

void ClickMachine::on_rising() noexcept {
    // A rise the depth signal held back for a frame counts from that frame.
    const Timestamp rose_at = late_ ? last_frame_ : crossed(settings_.press_rise);
    const bool in_time = static_cast<double>(rose_at - push_began_) / 1e6 <= settings_.push_seconds;
    // The rise must reach press_rise within push_seconds; holding it there may take longer.
    const bool high = rise_ >= settings_.press_rise && (in_time || held_since_);
    // A push brings the target closer where it is; an approach while moving sideways (the
    // hand wandering, walking in at an angle) carries it along. Against the target's own size
    // where the push began: the baseline is on the depth signal's scale, which every step it
    // took out has shrunk (to a third of the size on some clips), and with it the travel.
    const double size = push_raw_ > 0.0 ? push_raw_ : baseline_;
    // The region's steps since the push began moved the centroid, not the hand, as far as they
    // add up to little of its size; the position has them as far as its smoothing passed them.
    cv::Point2d travel = where_ - push_from_;
    // Jumps from before the push that the smoothing is still passing on are left out too.
    // Past the cap only its share of them: a flicker that jumps past it for a frame and comes
    // half-way back is still the region's, while a swipe's steps, several times the cap, are
    // mostly travel.
    if (settings_.push_region_jump > 0.0) {
        const double jumps = cv::norm(region_jumps_ - push_region_jumps_);
        const double cap = settings_.push_region_jump * size;
        const double share = jumps <= cap ? 1.0 : cap / jumps;
        travel -= (region_offset_ - push_region_offset_) * share;
    }
    // Judged on frames whose centroid did not jump: a region that leaks for one frame is given
    // back on the next with its centroid, and its jump leaves the travel then; a swipe's travel
    // is still there on its next frame. No press comes on a jumped frame either (below).
    const bool carried =
        settings_.push_travel > 0.0 && !jumped_ && cv::norm(travel) > settings_.push_travel * size;
    // Half way there, the press waits travel_hold_seconds for the rest to show.
    travelled_ = travelled_ || (settings_.push_travel > 0.0 &&
                                cv::norm(travel) > 0.5 * settings_.push_travel * size);
    // A push grows frame after frame; the bob of a step or a wobble goes up and down.
    push_peak_ = std::max(push_peak_, scale_);
    const bool dipped =
        settings_.push_dip > 0.0 && scale_ < push_peak_ * (1.0 - settings_.push_dip);
    if (rise_ <= settings_.start_rise) {
        state_ = ClickState::idle;
        held_since_.reset();
        follow_baseline();
    } else if (!carried && held(high && !jumped_, press_crossed())) {
        // Not on a frame whose centroid jumped, and the hold starts over after it: a push grows
        // about a steady centroid, while a hand setting off on a swipe smears into a trail
        // (+20-30% for a frame or two) and then jumps away.
        // Before the dip: at 10 fps a quick push's last frame in is also its first frame back.
        confirm();
    } else if (carried || dipped) {
        state_ = ClickState::drifting;
        held_since_.reset();
        follow_baseline();
    } else if (!in_time && !high) {
        state_ = ClickState::drifting;
        follow_baseline();
    }
}

void ClickMachine::on_drifting() noexcept {
    // Back under start_rise for press_hold_seconds, as a press is held: a region that drops a
    // piece for one frame while the target leans in (60 fps: two frames) leaves the baseline
    // behind the signal, and the next frame would start a push already at press_rise.
    if (held(rise_ <= settings_.start_rise, now_)) {
        state_ = ClickState::idle;
        held_since_.reset();
    }
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
    // The target's own size back where the push began has settled too, where the depth signal
    // took a step of the pull-back out and stays up (the rule of pulled_back()): the baseline
    // starts again from the signal, or the signal's leftover step would hold the next push off
    // (the second push of a double click) or press by itself.
    const bool back = settings_.glitch_jump > 0.0 && push_raw_ > 0.0 &&
                      raw_ <= push_raw_ * (1.0 + settings_.start_rise);
    if (seconds_since(released_at_) >= settings_.refractory_seconds &&
        (rise_ <= settings_.start_rise || back)) {
        state_ = ClickState::idle;
        if (rise_ > settings_.start_rise) baseline_ = scale_;
    }
    follow_baseline();
}

}  // namespace raypoint::core
