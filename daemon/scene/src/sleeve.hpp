// SPDX-License-Identifier: MIT
#pragma once
// The forearm in its sleeve behind a hand: from the wrist along the hand's axis until well past
// the frame's border, a little wider than the wrist (a cuff), shaded as a cylinder of cloth
// with soft folds. It moves with the hand and is drawn behind it; it is never the truth.

#include <opencv2/core.hpp>

#include "placement.hpp"
#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

class Sleeve {
  public:
    Sleeve(const Placement& hand, cv::Size frame);

    // The pixels it may touch, within the frame.
    cv::Rect bounds() const;
    // Adds weight x coverage (0..1, anti-aliased over one pixel) to acc (CV_32F, roi's size).
    void add_coverage(cv::Rect roi, float weight, cv::Mat& acc) const;
    // CV_32FC3 over roi: the cloth's colour at full light, continued beyond the outline.
    cv::Mat colour(cv::Rect roi, const Colour& cloth) const;

  private:
    // Columns [first, last) of row y that may lie within `reach` of the axis.
    std::pair<int, int> row_span(int y, double reach, cv::Rect roi) const;

    cv::Size frame_;
    cv::Point2d start_;  // the wrist's lower end, continuous pixels
    cv::Point2d axis_;   // unit direction toward the elbow
    double length_;      // pixels: past the frame from anywhere in it
    double radius_;      // pixels
};

}  // namespace raypoint::scene
