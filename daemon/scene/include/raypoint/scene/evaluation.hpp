// SPDX-License-Identifier: MIT
#pragma once
// Scores a tracker's output against a rendered clip's truth by the project's scoring method
// (docs/scoring.md), so the scene tests measure what every accuracy figure in docs/ measures.

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/tracker.hpp"
#include "raypoint/scene/truth.hpp"

namespace raypoint::scene {

struct Evaluation {
    int scored_frames = 0;  // target present and moving, from 1 s after it entered
    int on_target = 0;      // of those, the reported centroid lies on the target
    double tracked() const { return scored_frames == 0 ? 0.0 : double(on_target) / scored_frames; }
    std::optional<double> median_centroid_error;  // pixels at 160x120, frames on target
    std::optional<double> median_area_error;      // relative, frames on target
    std::optional<double> depth_correlation;      // position z against 1 / true depth
    // From the first frame the target moves to the first frame a target is reported.
    std::optional<double> detection_delay;  // seconds
};

class Evaluator {
  public:
    // The centroid counts as on target within this many pixels of a 160x120 image of the mask.
    static constexpr double on_target_pad = 4.0;
    static constexpr double grace_seconds = 1.0;

    void add(const Truth& truth, const cv::Mat& mask, const core::FrameResult& result);
    Evaluation result() const;

  private:
    struct Sample {
        bool scored = false;
        bool on_target = false;
        double centroid_error = 0.0;
        std::optional<double> area_error;
        std::optional<double> z;
        double inverse_depth = 0.0;
    };
    std::vector<Sample> samples_;
    std::optional<double> entered_at_;
    std::optional<double> first_motion_at_;
    std::optional<double> first_detection_at_;
};

}  // namespace raypoint::scene
