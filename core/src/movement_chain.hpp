// SPDX-License-Identifier: MIT
#pragma once
// The movement's chain: a point that follows the moving thing from frame to frame by where its
// movement leads, the pixels that moved in the last two frames and now differ from the scene
// more than they did a frame before (the target has arrived there; where it left, the scene
// shows again). It stays where it was when nothing moves near it. A small waving hand whose
// region the edges cannot close (fingers and motion blur at 160x120) leaks into the body or the
// window beside it; its movement still leads (TrackingSettings::follow_movement).
//
// Pure: allocates on the first frame and when the size changes only; no exceptions.

#include <array>
#include <optional>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"

namespace raypoint::core::detail {

class MovementChain {
  public:
    // `color`: the filtered working frame (CV_8UC3). Keeps it, blends the frame before into
    // the scene's running average and takes the differences the other calls read.
    void update(const cv::Mat& color, Timestamp timestamp) noexcept;
    // This frame's point (working pixels): the mean shift from the last one, else from
    // `target` (the tracker's centroid). Where it was when nothing moved near it; nothing
    // before the tracker's first target.
    std::optional<cv::Point2f> follow(std::optional<cv::Point2f> target) noexcept;
    // The frame time at which the point last found movement to follow.
    std::optional<Timestamp> led_at() const noexcept { return led_at_; }
    // The tracker agrees with the chain: it goes on from the tracker's centroid.
    void restart(cv::Point2f at) noexcept { point_ = at; }
    // The share of this frame's difference within `radius` working pixels of `centre`
    // (1 without a difference), both counted over the pixels at 0.15 of the strongest
    // difference or more.
    double share_near(cv::Point2f centre, double radius) const noexcept;
    void reset() noexcept;

  private:
    // The movement's leading part found by mean shift from `start`; nothing when the frame
    // moved less than a target does, or no strong difference is near `start`.
    std::optional<cv::Point2f> locate(cv::Point2f start) const noexcept;
    // The difference's centre of mass over its strong pixels within half_window working pixels of
    // `at`, again from there until it moves less than a fifth of a pixel.
    std::optional<cv::Point2f> shift(cv::Point2f at) const noexcept;
    // The centre of mass of the difference's pixels at strong_share of the strongest in `box`.
    std::optional<cv::Point2f> strong_centre(cv::Rect box) const noexcept;

    cv::Mat current_;                // CV_8UC3: this frame
    cv::Mat previous_;               // CV_8UC3: the frame before
    cv::Mat before_previous_;        // CV_8UC3: the frame two back
    cv::Mat scene_;                  // CV_32FC3: the running average of the frames before this one
    cv::Mat difference_;             // CV_8U: |current - previous|, the largest channel
    cv::Mat channels_;               // CV_8UC3: |current - previous|, each channel
    std::array<cv::Mat, 3> planes_;  // channels_, split
    cv::Mat counted_;                // CV_8U: difference_ where share_near counts it, else 0
    int frames_ = 0;                 // frames kept since the last reset, up to 3
    int strongest_ = 0;              // the largest value of difference_
    double total_ = 0.0;             // the sum of difference_ over the pixels share_near counts
    Timestamp frame_time_ = 0;       // the latest frame's
    std::optional<cv::Point2f> point_;
    std::optional<Timestamp> led_at_;
};

}  // namespace raypoint::core::detail
