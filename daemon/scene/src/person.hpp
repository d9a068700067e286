// SPDX-License-Identifier: MIT
#pragma once
// A person sitting behind the target, as a webcam on a monitor sees its user: head, neck,
// shoulders and shirt down to the frame's bottom, skin of the target's colour family. They
// breathe, turn the head and sway a little, so they move between frames as a real person does.

#include <cstdint>

#include <opencv2/core.hpp>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

class Person {
  public:
    Person(cv::Size frame, const Colour& skin, std::uint64_t seed);

    // Draws the person at time t (s) over `light` (CV_32FC3, the frame's background at full
    // light, vignetted), vignetted by `vignette` (CV_32F).
    void draw(double t, const cv::Mat& vignette, cv::Mat& light) const;

  private:
    cv::Size frame_;
    double px_;  // pixels per pixel of a 480-line frame
    cv::Scalar skin_;
    cv::Scalar hair_;
    cv::Scalar shirt_;
    double x_;     // body centre, pixels
    double head_;  // head centre height, pixels
    double turn_phase_;
    double sway_phase_;
    double nod_phase_;
};

}  // namespace raypoint::scene
