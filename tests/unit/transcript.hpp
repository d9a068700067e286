// SPDX-License-Identifier: MIT
#pragma once
// Transcript tests for the state machine: a scripted FrameEvidence, one table row a frame.
// Frame features in (time, movement, detection, estimates, colours), state and events out.

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/core/state_machine.hpp"

namespace raypoint::test {

using core::Estimate;
using core::LossReason;
using core::TrackerState;

// What current_color(at) answers in one frame: `fallback` except at the listed spots.
struct Paint {
    cv::Vec3f fallback;
    std::vector<std::pair<cv::Point2f, cv::Vec3f>> spots;

    cv::Vec3f at(cv::Point2f p) const {
        for (const auto& [where, colour] : spots) {
            if (std::abs(where.x - p.x) < 0.5F && std::abs(where.y - p.y) < 0.5F) return colour;
        }
        return fallback;
    }
};

// What the frame did besides its state.
enum class Event {
    none,
    acquired,
    recovered,
    too_small,
    too_large,
    still,
    left,
    no_point,
    failed,
    elsewhere
};

struct Row {
    double seconds;
    double movement;
    std::optional<cv::Point2f> detect;
    std::vector<Estimate> estimates;  // answers to successive estimate() calls
    Paint paint;                      // this frame; previous_color() reads the previous row's
    TrackerState state;               // expected after the frame
    Event event = Event::none;
    // movement_near()'s answer around any point; unset: all the movement is there.
    std::optional<double> near = std::nullopt;
    // change()'s answer (TrackingSettings::change_seconds): what differs from the quiet frame.
    std::optional<cv::Point2f> change = std::nullopt;
    // quiet_color()'s answer anywhere: the quiet frame's colour.
    std::optional<cv::Vec3f> quiet = std::nullopt;
};

// Records every question the state machine asks.
class Script final : public core::FrameEvidence {
  public:
    const Row* row = nullptr;
    const Paint* before = nullptr;
    std::size_t used = 0;
    std::vector<cv::Point2f> estimated_at;
    mutable std::vector<cv::Point2f> painted_at;
    bool kept_quiet = false;    // keep_quiet_frame() was called
    bool asked_change = false;  // change() was called

    double movement() const noexcept override { return row->movement; }
    double movement_near(cv::Point2f, float) const noexcept override {
        return row->near.value_or(row->movement);
    }
    std::optional<cv::Point2f> detect() noexcept override { return row->detect; }
    Estimate estimate(cv::Point2f inner) noexcept override {
        estimated_at.push_back(inner);
        if (used >= row->estimates.size()) {
            ADD_FAILURE() << "unscripted estimate() at " << inner;
            return Estimate{inner, 0.0, inner, 1};
        }
        return row->estimates[used++];
    }
    cv::Vec3f current_color(cv::Point2f at) const noexcept override {
        painted_at.push_back(at);
        return row->paint.at(at);
    }
    cv::Vec3f previous_color(cv::Point2f at) const noexcept override {
        return before != nullptr ? before->at(at) : cv::Vec3f();
    }
    void keep_quiet_frame() noexcept override { kept_quiet = true; }
    std::optional<cv::Point2f> change(double) noexcept override {
        asked_change = true;
        return row->change;
    }
    std::optional<cv::Vec3f> quiet_color(cv::Point2f) const noexcept override { return row->quiet; }
};

struct Played {
    std::vector<core::StepResult> results;
    std::vector<std::vector<cv::Point2f>> estimated_at;  // per frame
    std::vector<std::vector<cv::Point2f>> painted_at;    // per frame
    std::vector<bool> kept_quiet;                        // per frame
    std::vector<bool> asked_change;                      // per frame
};

inline Event event_of(const core::StepResult& r) {
    if (r.acquired) return Event::acquired;
    if (r.recovered) return Event::recovered;
    switch (r.loss) {
        case LossReason::none:
            return r.lost ? Event::failed : Event::none;
        case LossReason::too_small:
            return Event::too_small;
        case LossReason::too_large:
            return Event::too_large;
        case LossReason::still:
            return Event::still;
        case LossReason::left:
            return Event::left;
        case LossReason::no_recovery_point:
            return Event::no_point;
        case LossReason::recovery_failed:
            return Event::failed;
        case LossReason::elsewhere:
            return Event::elsewhere;
    }
    return Event::none;
}

// Steps `machine` through `rows`, checking each row's state and event.
inline Played play(core::StateMachine& machine, const std::vector<Row>& rows) {
    Played played;
    const Paint* before = nullptr;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& row = rows[i];
        SCOPED_TRACE(::testing::Message() << "frame " << i << " at " << row.seconds << " s");
        Script script;
        script.row = &row;
        script.before = before;
        const auto result =
            machine.step(static_cast<core::Timestamp>(std::llround(row.seconds * 1e6)), script);
        EXPECT_EQ(core::to_string(result.state), core::to_string(row.state));
        EXPECT_EQ(static_cast<int>(event_of(result)), static_cast<int>(row.event));
        EXPECT_EQ(result.lost, row.event >= Event::too_small);
        EXPECT_EQ(result.has_target, result.state == TrackerState::tracking);
        // The frame a search picks its target has no area; every other target frame has one.
        EXPECT_EQ(result.area_known, result.has_target && !result.acquired);
        EXPECT_EQ(script.used, row.estimates.size()) << "scripted estimates left unused";
        played.results.push_back(result);
        played.estimated_at.push_back(script.estimated_at);
        played.painted_at.push_back(script.painted_at);
        played.kept_quiet.push_back(script.kept_quiet);
        played.asked_change.push_back(script.asked_change);
        before = &row.paint;
    }
    return played;
}

}  // namespace raypoint::test
