// SPDX-License-Identifier: MIT
#pragma once
// What the state machine's transcript tests share: the target's spot and colours, an estimate
// there, and the paper's tracking settings without the startup wait.

#include <optional>

#include "raypoint/core/settings.hpp"
#include "transcript.hpp"

namespace raypoint::test::machine {

using core::Estimate;
using core::TrackingSettings;

inline constexpr auto none = std::nullopt;
inline const cv::Point2f P(60.0F, 50.0F);  // where the target is found
inline const cv::Vec3f wall(200.0F, 200.0F, 200.0F);
inline const cv::Vec3f skin(60.0F, 90.0F, 180.0F);

inline cv::Vec3f plus(cv::Vec3f c, float b, float g, float r) {
    return c + cv::Vec3f(b, g, r);
}

// An estimate whose inner point is `inner`; the centroid is put 2 px right and 1 down of it.
inline Estimate est(cv::Point2f inner, double area) {
    return Estimate{inner + cv::Point2f(2.0F, 1.0F), area, inner, 3};
}

// The paper's tracking settings with no startup wait (INITIALIZING has its own tests).
inline TrackingSettings paper(double idle_seconds = 2.0, bool keep_still = false) {
    TrackingSettings s = core::paper_settings().tracking;
    s.startup_seconds = 0.0;
    s.idle_seconds = idle_seconds;
    s.keep_still_target = keep_still;
    return s;
}

inline const cv::Size paper_size(160, 120);

}  // namespace raypoint::test::machine
