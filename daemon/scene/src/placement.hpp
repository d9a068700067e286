// SPDX-License-Identifier: MIT
#pragma once
// A sprite placed at a pose on the frame: which pixels it may touch and how to sample its
// textures there.

#include <array>

#include <opencv2/core.hpp>

#include "camera.hpp"
#include "sprite.hpp"
#include "trajectory.hpp"

namespace raypoint::scene {

class Placement {
  public:
    Placement(const Sprite& sprite, const Camera& camera, double size_m, const Pose& pose);

    // Pixels the outline can reach, plus two for anti-aliasing; may extend past the frame.
    cv::Rect bounds() const;
    // Frame positions (continuous pixels) of the outline box's corners.
    std::array<cv::Point2d, 4> corners() const;

    // Adds weight x coverage (0..1, anti-aliased over one pixel) to acc, a CV_32F image of
    // roi's size.
    void add_coverage(cv::Rect roi, float weight, cv::Mat& acc) const;
    // CV_8U over roi: 255 where the outline's signed distance is <= 0 (coverage >= 50%).
    cv::Mat mask(cv::Rect roi) const;
    // CV_32FC3 over roi: the sprite's colour at full light.
    cv::Mat colour(cv::Rect roi) const;

    // A point in the sprite's units (y down the target) on the frame (continuous pixels), the
    // frame direction of the sprite's +y, and the pixels a unit spans.
    cv::Point2d to_frame(cv::Point2d units) const;
    cv::Point2d down() const { return {-sin_, cos_}; }
    double px_per_unit() const { return px_per_unit_; }
    const Sprite& sprite() const { return sprite_; }

  private:
    cv::Mat sample(const cv::Mat& texture, cv::Rect roi, int border, double border_value) const;

    const Sprite& sprite_;
    cv::Point2d centre_;  // continuous pixels
    double px_per_unit_;
    double cos_;
    double sin_;
};

}  // namespace raypoint::scene
