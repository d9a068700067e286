// SPDX-License-Identifier: MIT
#pragma once
// Scenes and measures the renderer's tests share.

#include <opencv2/core.hpp>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene::render_testing {

// A still target at (x, y, depth) from t = 0: no entry, no noise.
inline SceneSpec still(Target target, double depth, double x = 0.5, double y = 0.5) {
    SceneSpec s;
    s.target = target;
    s.seconds = 1;
    s.empty_seconds = 0;
    s.noise_sigma = 0;
    s.path = {{0, x, y, depth}};
    return s;
}

inline double mean_grey(const cv::Mat& bgr, cv::Rect area) {
    const cv::Scalar m = cv::mean(bgr(area));
    return (m[0] + m[1] + m[2]) / 3;
}

}  // namespace raypoint::scene::render_testing
