// SPDX-License-Identifier: MIT
#include "raypoint/core/state_machine.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace raypoint::core {
namespace {

// The paper's thresholds are sums over 160x120 pixels (section 4.2).
constexpr double paper_working_pixels = 160.0 * 120.0;

}  // namespace

std::string_view to_string(TrackerState state) noexcept {
    switch (state) {
        case TrackerState::initializing:
            return "initializing";
        case TrackerState::searching:
            return "searching";
        case TrackerState::tracking:
            return "tracking";
        case TrackerState::validating:
            return "validating";
        case TrackerState::recovering:
            return "recovering";
    }
    return "?";
}

std::string_view to_string(LossReason reason) noexcept {
    switch (reason) {
        case LossReason::none:
            return "none";
        case LossReason::too_small:
            return "too-small";
        case LossReason::too_large:
            return "too-large";
        case LossReason::still:
            return "still";
        case LossReason::left:
            return "left";
        case LossReason::no_recovery_point:
            return "no-recovery-point";
        case LossReason::recovery_failed:
            return "recovery-failed";
        case LossReason::elsewhere:
            return "elsewhere";
    }
    return "?";
}

StateMachine::StateMachine(const TrackingSettings& settings, cv::Size working_size)
    : settings_(settings),
      working_size_(working_size),
      working_area_(static_cast<double>(working_size.area())),
      search_threshold_(settings.search_threshold * working_area_ / paper_working_pixels),
      idle_threshold_(settings.idle_threshold * working_area_ / paper_working_pixels) {}

float StateMachine::color_distance(cv::Vec3f a, cv::Vec3f b) noexcept {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

StepResult StateMachine::step(Timestamp timestamp, FrameEvidence& evidence) noexcept {
    now_ = timestamp;
    evidence_ = &evidence;
    result_ = StepResult{};
    bool finished = false;
    while (!finished) {
        switch (state_) {
            case TrackerState::initializing:
                finished = on_initializing();
                break;
            case TrackerState::searching:
                finished = on_searching();
                break;
            case TrackerState::tracking:
                finished = on_tracking();
                break;
            case TrackerState::validating:
                finished = on_validating();
                break;
            case TrackerState::recovering:
                finished = on_recovering();
                break;
        }
    }
    result_.state = state_;
    evidence_ = nullptr;
    return result_;
}

// Waits startup_seconds of frame time from the first frame (paper: the camera's automatic
// shutter settles); the frame that ends the wait already counts as the first searched one's
// predecessor.
bool StateMachine::on_initializing() noexcept {
    if (!started_at_) started_at_ = now_;
    if (now_ - *started_at_ >= seconds_to_us(settings_.startup_seconds)) {
        state_ = TrackerState::searching;
    }
    return true;
}

// Movement over the search threshold picks a target at the centre of mass of the difference.
// Estimation and validation start with the next frame: validating now would compare the target
// with the background it has just covered.
bool StateMachine::on_searching() noexcept {
    if (evidence_->movement() <= search_threshold_) {
        if (const auto found = quiet_change(true)) start_target(*found);
        return true;
    }
    moved_since_quiet_ = true;
    quiet_since_.reset();
    const auto found = evidence_->detect();
    if (!found) return true;
    start_target(*found);
    return true;
}

// A quiet frame is kept while nothing has moved since the last (in SEARCHING only: a tracked
// target must not become part of the quiet scene). After movement over the search threshold,
// the first frame change_seconds into the quiet (at or under idle_threshold) looks once for
// what changed; the quiet frame is kept again from the next quiet frame on, so movement that
// passed through, or a target that came and left, is not looked for twice. Frame time, so a
// recording replays as it ran live.
std::optional<cv::Point2f> StateMachine::quiet_change(bool keep) noexcept {
    if (settings_.change_seconds <= 0.0) return std::nullopt;
    if (evidence_->movement() > idle_threshold_) {
        quiet_since_.reset();
        return std::nullopt;
    }
    if (!quiet_since_) quiet_since_ = now_;
    if (!moved_since_quiet_) {
        if (keep) evidence_->keep_quiet_frame();
        return std::nullopt;
    }
    if (now_ - *quiet_since_ < seconds_to_us(settings_.change_seconds)) return std::nullopt;
    moved_since_quiet_ = false;
    return evidence_->change(search_threshold_);
}

// A target taken by mistake as the movement came in (the wall beside an entering hand, the
// floor under a 10 fps smear) is scenery: its inner point looks as it did in the quiet frame,
// within color_tolerance. When the change lies in another region, of a target's size, that
// region is picked instead. A tracked target that came in itself looks different from the quiet
// frame and is kept, whatever else changed (a ball held by a moving hand).
bool StateMachine::changed_elsewhere(const Estimate& estimate) noexcept {
    const auto found = quiet_change(false);
    if (!found) return false;
    const auto before = evidence_->quiet_color(estimate.inner);
    const auto tolerance = static_cast<float>(settings_.color_tolerance);
    if (!before || color_distance(*before, evidence_->current_color(estimate.inner)) > tolerance)
        return false;
    const Estimate there = evidence_->look(*found);
    result_.iterations += there.iterations;
    if (area_check(there.area) != LossReason::none) return false;
    // The same region: centroids a quarter of its size apart at most, areas within a factor 2.
    const double larger = std::max(there.area, estimate.area);
    const double smaller = std::min(there.area, estimate.area);
    const double apart =
        std::hypot(there.centroid.x - estimate.centroid.x, there.centroid.y - estimate.centroid.y);
    if (apart <= 0.25 * std::sqrt(larger) && smaller >= 0.5 * larger) return false;
    // A switch, not a loss: the frame has a target, picked where the change is.
    start_target(*found);
    return true;
}

void StateMachine::start_target(cv::Point2f at) noexcept {
    forget_target();
    pick(at);
    picked_at_ = now_;
    state_ = TrackerState::tracking;
}

bool StateMachine::on_tracking() noexcept {
    if (evidence_->movement() < idle_threshold_) {
        if (!still_since_) still_since_ = now_;
    } else {
        still_since_.reset();
    }
    if (still_too_long() && !settings_.keep_still_target) {
        drop_target(LossReason::still);
        return true;
    }
    if (pick_moved_on()) return true;
    candidate_ = evidence_->estimate(inner_);
    result_.iterations += candidate_.iterations;
    if (changed_elsewhere(candidate_)) return true;
    if (moving_elsewhere(candidate_)) {
        drop_target(LossReason::elsewhere);
        return true;
    }
    if (const LossReason reason = area_check(candidate_.area); reason != LossReason::none) {
        // Not a target's first estimate: from the search's point, the recovery points find
        // neighbours of the target's colour.
        if (reason == LossReason::too_small && settings_.recover_small && estimated_) {
            state_ = TrackerState::recovering;
            return false;
        }
        drop_target(reason);
        return true;
    }
    if (held_back()) return true;
    state_ = TrackerState::validating;
    return false;
}

// A hand's projection cannot double in 1/30 s: that is its region merging with something of its
// colour behind it (a body, a ball passing, a shelf through a gap in the outline). The last
// accepted estimate stands, for at most growth_hold: a region that stays that large is taken.
// The limit compounds over the time since that estimate (x8 over 0.1 s at 10 fps), so a quick
// push at a low frame rate is not held.
bool StateMachine::held_back() noexcept {
    if (settings_.max_growth <= 0.0 || !estimated_) return false;
    const double frames = std::max(1.0, static_cast<double>(now_ - last_accepted_at_) * 30e-6);
    if (candidate_.area <= std::pow(settings_.max_growth, frames) * last_accepted_.area) {
        held_since_.reset();
        return false;
    }
    if (!held_since_) held_since_ = now_;
    if (now_ - *held_since_ >= seconds_to_us(settings_.growth_hold)) {
        held_since_.reset();
        return false;
    }
    result_.estimate = last_accepted_;
    result_.has_target = true;
    result_.area_known = true;
    result_.held = true;
    return true;
}

// The previous inner point in the previous frame against the new one in this frame.
bool StateMachine::on_validating() noexcept {
    const cv::Vec3f before = evidence_->previous_color(inner_);
    const cv::Vec3f now = evidence_->current_color(candidate_.inner);
    if (color_distance(before, now) > static_cast<float>(settings_.color_tolerance)) {
        state_ = TrackerState::recovering;
        return false;
    }
    // A target kept while still must still look like the target did when it last moved;
    // otherwise it has left and the inner point sits on background.
    if (still_too_long() &&
        color_distance(reference_color_, now) > static_cast<float>(settings_.color_tolerance)) {
        drop_target(LossReason::left);
        return true;
    }
    accept(candidate_);
    state_ = TrackerState::tracking;
    return true;
}

// Recovery points 10 and 20 px away in the 8 directions around the failed inner point; the one
// that best matches the previous inner point's colour is re-estimated and validated once more.
bool StateMachine::on_recovering() noexcept {
    static constexpr std::array<std::array<int, 2>, 8> directions{
        {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
    result_.recovery_from = candidate_.inner;
    const cv::Vec3f before = evidence_->previous_color(inner_);
    const auto tolerance = static_cast<float>(settings_.color_tolerance);
    std::optional<cv::Point2f> best;
    float best_distance = tolerance;
    for (const int offset : {settings_.recovery_near, settings_.recovery_far}) {
        for (const auto& d : directions) {
            const cv::Point2f point =
                candidate_.inner +
                cv::Point2f(static_cast<float>(d[0] * offset), static_cast<float>(d[1] * offset));
            if (point.x < 0 || point.y < 0 ||
                point.x > static_cast<float>(working_size_.width - 1) ||
                point.y > static_cast<float>(working_size_.height - 1)) {
                continue;
            }
            const float distance = color_distance(before, evidence_->current_color(point));
            if (distance <= best_distance) {
                best_distance = distance;
                best = point;
            }
        }
    }
    if (!best) {
        drop_target(LossReason::no_recovery_point);
        return true;
    }
    const Estimate recovered = evidence_->estimate(*best);
    result_.iterations += recovered.iterations;
    const bool matches =
        color_distance(before, evidence_->current_color(recovered.inner)) <= tolerance;
    const LossReason area = area_check(recovered.area);
    if (!matches || area != LossReason::none) {
        drop_target(matches ? area : LossReason::recovery_failed);
        return true;
    }
    result_.recovered = true;
    accept(recovered);
    state_ = TrackerState::tracking;
    return true;
}

// The pick is the centre of mass of the difference (paper 4.2). A target entering fast at a low
// frame rate has moved on by the next frame: the pick lies on the background it uncovered, which
// the difference shows (repick_difference grey levels or more a pixel of the colour patch), and an
// estimate from there is the wall or the floor, kept once the hand stops. The pick follows the
// movement instead, with the estimate from the next frame (validation compares two frames), for
// at most repick_seconds after the first pick: a target that never slows is estimated anyway.
bool StateMachine::pick_moved_on() noexcept {
    if (settings_.repick_difference <= 0 || estimated_ ||
        now_ - picked_at_ > seconds_to_us(settings_.repick_seconds) ||
        evidence_->movement() <= search_threshold_) {
        return false;
    }
    const int half = settings_.color_patch / 2;
    const double side = 2.0 * half + 1.0;
    if (evidence_->movement_near(inner_, static_cast<float>(half)) <
        settings_.repick_difference * side * side) {
        return false;
    }
    const auto found = evidence_->detect();
    if (!found) return false;
    pick(*found);
    return true;
}

// The inner point and the centroid at `at`, with no area this frame.
void StateMachine::pick(cv::Point2f at) noexcept {
    inner_ = at;
    result_.estimate = Estimate{at, 0.0, at, 0};
    result_.has_target = true;
    result_.acquired = true;
    reference_color_ = evidence_->current_color(at);
}

LossReason StateMachine::area_check(double area) const noexcept {
    const double fraction = area / working_area_;
    if (fraction < settings_.min_area) return LossReason::too_small;
    if (fraction > settings_.max_area) return LossReason::too_large;
    return LossReason::none;
}

bool StateMachine::still_too_long() const noexcept {
    return still_since_ && now_ - *still_since_ >= seconds_to_us(settings_.idle_seconds);
}

// A search threshold's worth of movement, hardly any of it on the target: the target is a still
// part of the scene the tracker locked on (a body, a sleeve, a shelf), and the hand is elsewhere.
// Not a target that had its share of the movement within abandon_grace: that is a hand slowing
// at the turn of a wave while something else moves (a ball or a person passing behind it).
// A frame at or under the search threshold restarts the time away (a waving hand dips under it at
// each turn), unless the last frame over it left the target none of the movement at all.
bool StateMachine::moving_elsewhere(const Estimate& estimate) noexcept {
    const double movement = evidence_->movement();
    if (settings_.abandon_seconds <= 0.0) return false;
    if (movement <= search_threshold_) {
        if (!none_around_) elsewhere_since_.reset();
        return false;
    }
    const double around = evidence_->movement_near(estimate.centroid, motion_radius(estimate.area));
    none_around_ = around < settings_.abandon_still_share * movement;
    if (around >= settings_.abandon_share * movement) {
        elsewhere_since_.reset();
        owned_motion_at_ = now_;
        return false;
    }
    if (!elsewhere_since_) elsewhere_since_ = now_;
    if (owned_motion_at_ && now_ - *owned_motion_at_ < seconds_to_us(settings_.abandon_grace))
        return false;
    return now_ - *elsewhere_since_ >= seconds_to_us(settings_.abandon_seconds);
}

void StateMachine::drop_target(LossReason reason) noexcept {
    forget_target();
    state_ = TrackerState::searching;
    result_.loss = reason;
    result_.has_target = false;
    result_.lost = true;
}

void StateMachine::forget_target() noexcept {
    still_since_.reset();
    elsewhere_since_.reset();
    none_around_ = false;
    owned_motion_at_.reset();
    held_since_.reset();
    estimated_ = false;
    evidence_->forget_target();
}

void StateMachine::accept(const Estimate& estimate) noexcept {
    last_accepted_ = estimate;
    last_accepted_at_ = now_;
    inner_ = estimate.inner;
    estimated_ = true;
    result_.estimate = estimate;
    result_.has_target = true;
    result_.area_known = true;
    if (!still_since_) reference_color_ = evidence_->current_color(estimate.inner);
}

}  // namespace raypoint::core
