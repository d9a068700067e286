// SPDX-License-Identifier: MIT
#pragma once
// The tracking system's state machine (paper 4.2), one handler a state. It sees frames only
// through FrameEvidence, so transcript tests drive it with scripted features and the Tracker
// with real images; docs/state-machine.md is its diagram and must change with it.

#include <cmath>
#include <optional>

#include <opencv2/core.hpp>

#include "raypoint/core/estimator.hpp"
#include "raypoint/core/frame.hpp"
#include "raypoint/core/settings.hpp"
#include "raypoint/core/tracker_state.hpp"

namespace raypoint::core {

// Half the side of the square around a region of `area` square working pixels that holds the
// movement it makes: the region's own square and 2 pixels more, as a moving target's difference
// lies along its outline, inside and out.
inline float motion_radius(double area) noexcept {
    return static_cast<float>(0.75 * std::sqrt(area) + 2.0);
}

// What the state machine may ask of the current frame. Points are in working pixels.
class FrameEvidence {
  public:
    virtual ~FrameEvidence() = default;
    // Global inter-frame movement, summed over the working pixels.
    virtual double movement() const noexcept = 0;
    // The same sum over the square of half-side `radius` around `centre`, clipped to the image.
    virtual double movement_near(cv::Point2f centre, float radius) const noexcept = 0;
    // SEARCHING: the centre of mass of the difference image, if it has any mass.
    virtual std::optional<cv::Point2f> detect() noexcept = 0;
    virtual Estimate estimate(cv::Point2f inner) noexcept = 0;
    // The same estimate, leaving what estimate() carries to the tracked target's next one as it
    // was: a look at a region that may not become the target.
    virtual Estimate look(cv::Point2f inner) noexcept { return estimate(inner); }
    // Mean BGR of the colour_patch square centred at `at`, in this frame or the previous one.
    virtual cv::Vec3f current_color(cv::Point2f at) const noexcept = 0;
    virtual cv::Vec3f previous_color(cv::Point2f at) const noexcept = 0;
    // The target was dropped, or a new one picked: what estimate() kept about the old one goes.
    virtual void forget_target() noexcept {}
    // TrackingSettings::change_seconds: this frame becomes the quiet scene; change() is the
    // centre of mass of what differs from it, when that sums to more than `threshold` (the
    // movement's units), and nothing without a quiet frame.
    virtual void keep_quiet_frame() noexcept {}
    virtual std::optional<cv::Point2f> change(double threshold) noexcept {
        (void)threshold;
        return std::nullopt;
    }
    // Mean BGR of the colour_patch square centred at `at` in the quiet frame, if one is kept.
    virtual std::optional<cv::Vec3f> quiet_color(cv::Point2f at) const noexcept {
        (void)at;
        return std::nullopt;
    }
};

// What one frame did to the state machine.
struct StepResult {
    TrackerState state = TrackerState::initializing;  // after the frame
    bool has_target = false;
    bool area_known = false;  // false on the frame a search picks a target (paper 4.2)
    Estimate estimate;        // valid when has_target; working pixels
    bool acquired = false;    // a target was picked this frame (SEARCHING, or repick_difference)
    bool recovered = false;   // RECOVERING succeeded this frame
    bool held = false;        // TRACKING held a candidate that grew too fast (max_growth) back
    bool lost = false;        // the target was dropped this frame
    LossReason loss = LossReason::none;
    int iterations = 0;
    // RECOVERING ran this frame: the failed inner point its recovery points surround (working
    // pixels, the offsets recovery_near and recovery_far in 8 directions), for drawing.
    std::optional<cv::Point2f> recovery_from;
};

class StateMachine {
  public:
    StateMachine(const TrackingSettings& settings, cv::Size working_size);

    StepResult step(Timestamp timestamp, FrameEvidence& evidence) noexcept;
    TrackerState state() const noexcept { return state_; }

    // Sum of |channel difference| of two patch means; colours match at or below the tolerance.
    static float color_distance(cv::Vec3f a, cv::Vec3f b) noexcept;

  private:
    // Each handler returns true when it has finished the frame; false passes the same frame on
    // to the state it switched to (TRACKING -> VALIDATING -> RECOVERING happen in one frame).
    bool on_initializing() noexcept;
    bool on_searching() noexcept;
    bool on_tracking() noexcept;
    bool on_validating() noexcept;
    bool on_recovering() noexcept;

    LossReason area_check(double area) const noexcept;
    bool still_too_long() const noexcept;
    // Whether the movement has been away from the target for abandon_seconds.
    bool moving_elsewhere(const Estimate& estimate) noexcept;
    // Whether the candidate grew past max_growth and is held back (the last estimate reported).
    bool held_back() noexcept;
    // Whether the target moved on from a pick not yet estimated; the pick then follows it.
    bool pick_moved_on() noexcept;
    // TrackingSettings::change_seconds: what changed since the last quiet frame, once the scene
    // is quiet again after movement; `keep` keeps this frame as the quiet one when nothing has
    // moved since the last.
    std::optional<cv::Point2f> quiet_change(bool keep) noexcept;
    // Whether a target that is scenery was dropped for the change (a new pick this frame).
    bool changed_elsewhere(const Estimate& estimate) noexcept;
    void pick(cv::Point2f at) noexcept;
    // A new target at `at` (SEARCHING's pick, or a switch from a target that is scenery),
    // estimated from the next frame on; what was kept about any old one goes.
    void start_target(cv::Point2f at) noexcept;
    // The target is lost for `reason`: SEARCHING from the next frame.
    void drop_target(LossReason reason) noexcept;
    // What the tracker kept about the target goes (a loss, or a switch to another pick).
    void forget_target() noexcept;
    void accept(const Estimate& estimate) noexcept;

    TrackingSettings settings_;
    cv::Size working_size_;
    double working_area_;
    double search_threshold_;  // scaled to the working size
    double idle_threshold_;

    TrackerState state_ = TrackerState::initializing;
    std::optional<Timestamp> started_at_;
    std::optional<Timestamp> still_since_;
    // The last frame whose movement was over the search threshold with the target's share of
    // it around the target (TrackingSettings::abandon_grace).
    std::optional<Timestamp> owned_motion_at_;
    // TrackingSettings::max_growth: the last accepted estimate, when, and since when estimates
    // that grew too fast have been held back.
    Estimate last_accepted_{};
    Timestamp last_accepted_at_ = 0;
    std::optional<Timestamp> held_since_;
    Timestamp picked_at_ = 0;                   // when SEARCHING picked the target
    std::optional<Timestamp> elsewhere_since_;  // the target still, the scene's motion not
    // The last frame over the search threshold left the target under abandon_still_share of it.
    bool none_around_ = false;
    cv::Point2f inner_;          // the inner point after the previous frame
    Estimate candidate_;         // TRACKING's estimate, waiting for VALIDATING
    cv::Vec3f reference_color_;  // the target's colour the last time it moved
    bool estimated_ = false;     // the target has had an estimate accepted since it was picked
    // TrackingSettings::change_seconds: movement over the search threshold since the last quiet
    // frame was kept, and since when the movement has been at or under idle_threshold.
    bool moved_since_quiet_ = false;
    std::optional<Timestamp> quiet_since_;

    // The frame being stepped.
    Timestamp now_ = 0;
    FrameEvidence* evidence_ = nullptr;
    StepResult result_;
};

}  // namespace raypoint::core
