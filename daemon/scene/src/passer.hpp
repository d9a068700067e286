// SPDX-License-Identifier: MIT
#pragma once
// A second object passing behind the target: a matte ball crossing the picture from one side to
// the other, as a colleague's head, a cat or a thrown toy does behind a user's hand. Part of
// the background, never of the truth: a pointer must neither follow it nor click on it.

#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

class Passer {
  public:
    Passer(cv::Size frame, const SceneSpec& spec);

    // Draws every pass under way at time t (s) over `light` (CV_32FC3, the frame's background
    // at full light, vignetted), vignetted by `vignette` (CV_32F), blurred over `exposure`
    // seconds centred on t as the target is.
    void draw(double t, double exposure, const cv::Mat& vignette, cv::Mat& light) const;

  private:
    cv::Size frame_;
    std::vector<double> starts_;  // s
    double seconds_;              // one crossing
    double radius_;               // pixels
    double y_;                    // centre height, pixels
    cv::Vec3f colour_;            // BGR at full light
};

}  // namespace raypoint::scene
