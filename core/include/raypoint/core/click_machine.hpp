// SPDX-License-Identifier: MIT
#pragma once
// Click by depth: pushing the target toward the camera presses the left button, pulling it back
// releases it. Optionally ([click]): a push held still is a right click, two quick pushes a
// double click, a push held while moving up or down scrolls. A state machine, one handler a state;
// docs/pointer.md draws it and must change with it. Input is the target's scale, sqrt(area) of
// each frame through the depth signal (depth_signal.hpp), not the smoothed z, whose
// once-a-frame average peaks 0.2 s after a push does (docs/pointer.md). Frame time only.

#include <optional>
#include <string_view>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

enum class ClickState {
    inactive,  // no target, or tracked for less than min_tracking_seconds: never pressed
    idle,      // the scale is near its baseline, which follows it
    rising,    // the rise left start_rise: a push may be under way; the baseline is held
    // it rose too slowly, was carried sideways or fell back: not a push; no press until it is
    // back near the baseline
    drifting,
    pressed,     // the button is down, x and y are frozen; the baseline is held
    dragging,    // held pushed past drag_seconds: the button stays down, x and y move
    refractory,  // just released: no press for refractory_seconds nor before the rise settles
    // With right click or scroll on: pushed, no button yet; x and y frozen. Pulling back
    // clicks, moving drags or scrolls, holding still arms the right click.
    holding,
    // Held still for right_seconds, no button yet; x and y frozen. Pulling back right-clicks
    // (press and release), moving still drags or scrolls.
    right_armed,
    scrolling,  // no button: vertical motion turns the wheel; pulling back stops
};

std::string_view to_string(ClickState state) noexcept;

// What one frame did.
// Button changes go out in the order of the fields: double_click's whole click, press, release,
// right_press, right_release.
struct ClickStep {
    ClickState state = ClickState::inactive;  // after the frame
    bool double_click = false;                // with press: a whole left click before it
    bool press = false;                       // press the left button now
    bool release = false;                     // release it now
    bool right_press = false;
    bool right_release = false;
    // The push is confirmed now (PRESSED or HOLDING entered): motion emitted since the frame
    // `push_began` is undone, so the click lands where the user aimed, not where the push
    // carried the centroid.
    bool undo = false;
    Timestamp push_began = 0;
    double scroll = 0.0;  // SCROLLING: frame widths the target moved up this frame
};

class ClickMachine {
  public:
    explicit ClickMachine(const ClickSettings& settings) noexcept;

    // Before each step(): the centroid's jumps on the frames whose size step the depth signal
    // took out, summed since the target was picked (frame widths), and that sum as the
    // position's smoothing has passed it on (ClickSettings::push_region_jump). Zero: none.
    // step_offset: the same, as passed on, for the steps that DepthSignal::stepped() saw and
    // absorbed() left in; a held push's position leaves it out.
    void set_region(cv::Point2d jumps, cv::Point2d offset, cv::Point2d step_offset = {}) noexcept {
        region_jumps_ = jumps;
        region_offset_ = offset;
        step_offset_ = step_offset;
    }
    // scale: sqrt(area) of the tracked target, or nullopt when there is none (not TRACKING, or
    // the frame that picks a target). ready: tracked for min_tracking_seconds (PointerController
    // decides). Losing the target while the button is down releases it. where: the smoothed
    // position in frame widths on both axes (y down), read by HOLDING and SCROLLING only.
    // late: the scale's change on this frame happened on the previous one (the depth signal
    // gave back a step it had held for a frame), so push_seconds counts to that frame.
    // raw: sqrt(area) before the depth signal took steps out; 0: the same as scale.
    // absorbed: the depth signal took a step out on this frame (settle_seconds).
    // jumped: the centroid jumped on this frame (DepthSignal::jumped): no press on it.
    ClickStep step(Timestamp timestamp, std::optional<double> scale, bool ready,
                   cv::Point2d where = {}, bool late = false, double raw = 0.0,
                   bool absorbed = false, bool jumped = false) noexcept;

    // Pause, exit, signal: back to inactive. True when a button was down and must be released.
    bool release_all() noexcept;

    ClickState state() const noexcept { return state_; }
    double baseline() const noexcept { return baseline_; }  // sqrt(area), 0 before a target
    double rise() const noexcept { return rise_; }          // of the last frame with a target
    // The position a hold's move is judged by (frame widths), of the last frame stepped.
    cv::Point2d where() const noexcept { return last_where_; }

  private:
    void on_inactive() noexcept;
    void on_idle() noexcept;
    void on_rising() noexcept;
    void on_drifting() noexcept;
    void on_pressed() noexcept;
    void on_dragging() noexcept;
    void on_refractory() noexcept;
    void on_holding() noexcept;
    void on_right_armed() noexcept;
    void on_scrolling() noexcept;

    void confirm() noexcept;  // RISING's push reached the press: PRESSED or HOLDING
    void press_left() noexcept;
    // HOLDING, RIGHT_ARMED: past hold_radius from where the hold began, the drag or the scroll
    // starts (true).
    bool moved_while_held() noexcept;
    // HOLDING: since when the size has been still (still_since_), through a region's flicker.
    void follow_stillness() noexcept;

    void follow_baseline() noexcept;
    double seconds_since(Timestamp then) const noexcept;
    // When the rise crossed `level` between the previous frame and this one (linearly in the
    // scale); the previous frame's time when the rise was there already, this frame's when it
    // is not there yet.
    Timestamp crossed(double level) const noexcept;
    // The time `fraction` of the way from the previous frame to this one.
    Timestamp between_frames(double fraction) const noexcept;
    // Whether `condition` has held for press_hold_seconds up to this frame, counting from
    // `since` (no later than now) when it begins to hold on this frame; for jump_hold_seconds
    // when longer, if it began in RISING on the frame the rise came from under start_rise.
    bool held(bool condition, Timestamp since) noexcept;
    // RISING: when the rise crossed press_rise, placed between this frame and the previous one
    // when the push was under way on that frame already; this frame's time otherwise.
    Timestamp press_crossed() const noexcept;
    // PRESSED, DRAGGING, HOLDING, RIGHT_ARMED, SCROLLING (click_release.cpp): the signal's
    // level at or under which the push is pulled back; and when the signal came down through
    // `level`, placed between the frames, where the pull-back was under way on the previous
    // frame (this frame's time otherwise).
    double release_level() const noexcept;
    Timestamp release_crossed(double level) const noexcept;
    void release() noexcept;
    bool pulled_back() noexcept;  // PRESSED, DRAGGING: the release's condition
    // Whether a step the depth signal took out came within `seconds` (0: never).
    bool within_step(double seconds) const noexcept;

    ClickSettings settings_;
    ClickState state_ = ClickState::inactive;
    double baseline_ = 0.0;
    double rise_ = 0.0;
    Timestamp last_frame_ = 0;  // the previous frame with a target
    Timestamp push_began_ = 0;
    Timestamp rising_at_ = 0;  // the frame that entered RISING
    cv::Point2d push_from_;    // where the push began: the position of the frame before RISING
    cv::Point2d last_where_;
    // ClickSettings::push_region_jump: set_region()'s values, the last frame's, and the last
    // frame's before the push began.
    cv::Point2d region_jumps_;
    cv::Point2d region_offset_;
    cv::Point2d last_region_jumps_;
    cv::Point2d last_region_offset_;
    cv::Point2d push_region_jumps_;
    cv::Point2d push_region_offset_;
    cv::Point2d step_offset_;       // set_region()'s
    cv::Point2d held_step_offset_;  // HOLDING, RIGHT_ARMED: step_offset_ where held_at_ was set
    double last_raw_ = 0.0;         // the previous frame's raw scale
    double last_scale_ = 0.0;       // the previous frame's scale (the depth signal); 0: none
    double push_raw_ = 0.0;         // the raw scale on the frame before RISING
    double push_peak_ = 0.0;        // RISING: the largest scale since the push began
    Timestamp pressed_at_ = 0;
    Timestamp released_at_ = 0;
    // Since when the rise has been at press_rise (RISING) or at release_rise (PRESSED,
    // DRAGGING) without a break; nothing while it is not.
    std::optional<Timestamp> held_since_;
    double peak_ = 0.0;  // the largest sqrt(area) since the press
    // PRESSED, DRAGGING: since when the raw size has been back where the push began
    // (release_raw_seconds); reset by each press.
    std::optional<Timestamp> raw_back_since_;
    // The last left click's release, for double_seconds; nothing after a double click.
    std::optional<Timestamp> clicked_at_;
    bool doubled_ = false;  // the button down now came with a double click
    // HOLDING: where the hold began (x, y frame widths), and since when the target's size has
    // been still (within start_rise of still_scale_).
    cv::Point2d held_at_;
    bool held_jump_ = false;  // the hold began on the frame the rise jumped from the baseline
    bool travelled_ = false;  // RISING: the travel passed half of push_travel (travel_hold_seconds)
    double still_scale_ = 0.0;
    Timestamp still_since_ = 0;
    // HOLDING: the still size before still_scale_, and since when the target has been still at
    // one of the two; whether the size left it gradually (as a push does: only a step comes
    // back to it); when the size came to still_scale_; the last frame on which it jumped by
    // more than hold_rise per 1/30 s, and the last on which it stepped by more than hold_rise.
    double other_scale_ = 0.0;
    Timestamp other_since_ = 0;
    bool other_crept_ = false;
    Timestamp level_since_ = 0;
    Timestamp jumped_at_ = 0;
    Timestamp stepped_at_ = 0;
    // HOLDING: the largest size within hold_flicker_seconds, as a peak held until that long
    // after it was seen or a larger one comes (a flicker's large shape comes back within a
    // frame or two), and when it was seen.
    double peak_held_ = 0.0;
    Timestamp peak_held_at_ = 0;
    double scroll_y_ = 0.0;  // SCROLLING: y of the previous frame
    // The last frame on which the depth signal took a step out (settle_seconds).
    std::optional<Timestamp> absorbed_at_;

    // The frame being stepped.
    Timestamp now_ = 0;
    double scale_ = 0.0;
    double raw_ = 0.0;
    bool ready_ = false;
    bool late_ = false;
    bool jumped_ = false;
    cv::Point2d where_;
    ClickStep result_;
};

}  // namespace raypoint::core
