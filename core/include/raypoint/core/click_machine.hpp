// SPDX-License-Identifier: MIT
#pragma once
// Click by depth: pushing the target toward the camera presses the left button, pulling it back
// releases it. A state machine, one handler a state; docs/pointer.md draws it and must change
// with it. Input is the target's scale, sqrt(area): the raw estimate, not the smoothed z, whose
// once-a-frame average peaks 0.2 s after a push does (docs/pointer.md). Frame time only.

#include <optional>
#include <string_view>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

enum class ClickState {
    inactive,    // no target, or tracked for less than min_tracking_seconds: never pressed
    idle,        // the scale is near its baseline, which follows it
    rising,      // the rise left start_rise: a push may be under way; the baseline is held
    drifting,    // it rose too slowly to be a push: no press until it is back near the baseline
    pressed,     // the button is down, x and y are frozen; the baseline is held
    dragging,    // held pushed past drag_seconds: the button stays down, x and y move
    refractory,  // just released: no press for refractory_seconds nor before the rise settles
};

std::string_view to_string(ClickState state) noexcept;

// What one frame did.
struct ClickStep {
    ClickState state = ClickState::inactive;  // after the frame
    bool press = false;                       // press the left button now
    bool release = false;                     // release it now
    // With `press`: the last frame before the push began. Motion emitted after it is undone,
    // so the click lands where the user aimed, not where the push carried the centroid.
    Timestamp push_began = 0;
};

class ClickMachine {
  public:
    explicit ClickMachine(const ClickSettings& settings) noexcept;

    // scale: sqrt(area) of the tracked target, or nullopt when there is none (not TRACKING, or
    // the frame that picks a target). ready: tracked for min_tracking_seconds (PointerController
    // decides). Losing the target while the button is down releases it.
    ClickStep step(Timestamp timestamp, std::optional<double> scale, bool ready) noexcept;

    // Pause, exit, signal: back to inactive. True when the button was down and must be released.
    bool release_all() noexcept;

    ClickState state() const noexcept { return state_; }
    double baseline() const noexcept { return baseline_; }  // sqrt(area), 0 before a target
    double rise() const noexcept { return rise_; }          // of the last frame with a target

  private:
    void on_inactive() noexcept;
    void on_idle() noexcept;
    void on_rising() noexcept;
    void on_drifting() noexcept;
    void on_pressed() noexcept;
    void on_dragging() noexcept;
    void on_refractory() noexcept;

    void follow_baseline() noexcept;
    double seconds_since(Timestamp then) const noexcept;
    // Whether `condition` has held for press_hold_seconds up to this frame.
    bool held(bool condition) noexcept;
    void release() noexcept;
    bool pulled_back() noexcept;  // PRESSED, DRAGGING: the release's condition

    ClickSettings settings_;
    ClickState state_ = ClickState::inactive;
    double baseline_ = 0.0;
    double rise_ = 0.0;
    Timestamp last_frame_ = 0;  // the previous frame with a target
    Timestamp push_began_ = 0;
    Timestamp pressed_at_ = 0;
    Timestamp released_at_ = 0;
    // Since when the rise has been at press_rise (RISING) or at release_rise (PRESSED,
    // DRAGGING) without a break; nothing while it is not.
    std::optional<Timestamp> held_since_;
    double peak_ = 0.0;  // the largest sqrt(area) since the press

    // The frame being stepped.
    Timestamp now_ = 0;
    double scale_ = 0.0;
    bool ready_ = false;
    ClickStep result_;
};

}  // namespace raypoint::core
