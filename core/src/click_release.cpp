// SPDX-License-Identifier: MIT
// The click machine's release: when a push is pulled back, and what coming up does
// (click_machine.hpp; docs/pointer.md, "Pulled back").
#include <algorithm>

#include "raypoint/core/click_machine.hpp"

namespace raypoint::core {

void ClickMachine::release() noexcept {
    // Only a click (not a drag, not the second of a double) can be the first of a double.
    if (state_ == ClickState::pressed || state_ == ClickState::holding) {
        if (!result_.double_click && !doubled_) {
            clicked_at_ = now_;
        } else {
            clicked_at_.reset();
        }
    } else {
        clicked_at_.reset();
    }
    result_.release = state_ == ClickState::pressed || state_ == ClickState::dragging ||
                      state_ == ClickState::holding;
    state_ = ClickState::refractory;
    released_at_ = now_;
    held_since_.reset();
}

// The signal's highest level that is pulled back, the most lenient of: release_rise over the
// baseline; release_drop under the largest size since the press (a drag carries the target
// where it may look bigger); release_share of the largest rise (after such a drag neither of
// the others may be reached).
double ClickMachine::release_level() const noexcept {
    double level = baseline_ * (1.0 + settings_.release_rise);
    if (settings_.release_drop > 0.0) {
        level = std::max(level, peak_ * (1.0 - settings_.release_drop));
    }
    if (settings_.release_share > 0.0) {
        level = std::max(level, baseline_ + settings_.release_share * (peak_ - baseline_));
    }
    return level;
}

bool ClickMachine::pulled_back() noexcept {
    peak_ = std::max(peak_, scale_);
    const double level = release_level();
    // The target's own size back near where the push began is a pull-back even where the depth
    // signal took the pull-back's last step out as the region changing: at 10 fps, or with a
    // region that changes shape as the hand comes back, that step is 15-40% in one frame with
    // the centroid jumping, and the signal then stays up. Only the depth signal's steps part
    // raw and signal, so without them (glitch_jump 0) neither rule below applies.
    const bool home = settings_.glitch_jump > 0.0 && push_raw_ > 0.0 &&
                      raw_ <= push_raw_ * (1.0 + settings_.release_rise);
    // At once when the signal has come back by half of release_drop too: a region that
    // flickers to a smaller shape while the push is held drops the raw size alone.
    const bool back = home && scale_ <= peak_ * (1.0 - settings_.release_drop / 2.0);
    // After release_raw_seconds whatever the signal (the flicker comes back within a frame or
    // two), for a button that is down: a held gesture's size moves with the hand.
    if (!home || (state_ != ClickState::pressed && state_ != ClickState::dragging)) {
        raw_back_since_.reset();
    } else if (!raw_back_since_) {
        raw_back_since_ = now_;
    }
    if (settings_.release_raw_seconds > 0.0 && raw_back_since_ &&
        seconds_since(*raw_back_since_) >= settings_.release_raw_seconds)
        return true;
    return held(scale_ <= level || back, release_crossed(level));
}

// As press_crossed(), for the pull-back: at 10 fps the release waited a frame for its hold, and a
// double click's second push came inside the first one's refractory time. Where the previous
// frame was at least halfway down from the largest size to the release's level: a held push
// that dips for one frame (the region dropping a piece) is held from that frame as before.
Timestamp ClickMachine::release_crossed(double level) const noexcept {
    if (!(last_scale_ > level) || scale_ > level || now_ <= last_frame_) return now_;
    if (last_scale_ > level + 0.5 * (peak_ - level)) return now_;
    return between_frames((last_scale_ - level) / (last_scale_ - scale_));
}

}  // namespace raypoint::core
