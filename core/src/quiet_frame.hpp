// SPDX-License-Identifier: MIT
#pragma once
// The last quiet frame of the scene, and what differs from it now: where a target that came in
// and stopped is, when the difference of two frames no longer shows it
// (TrackingSettings::change_seconds).

#include <optional>

#include <opencv2/core.hpp>

namespace raypoint::core::detail {

class QuietFrame {
  public:
    // `color`: the filtered working frame (CV_8UC3). Allocates on the first call and when the
    // size changes; a failed allocation leaves no frame kept.
    void keep(const cv::Mat& color) noexcept;
    bool kept() const noexcept { return !frame_.empty(); }
    const cv::Mat& frame() const noexcept { return frame_; }
    // The centre of mass of |color - kept| (the largest of the three channels' differences a
    // pixel, less the paper's brightness offset: the largest of the `minima` smallest distinct
    // values, 4.1), when that sums to more than `threshold`; nothing without a kept frame of
    // `color`'s size and type. Every pixel over the offset weighs in: the change is the
    // target's whole projection, not a moving outline, and the strongest half of it can be a
    // few pixels where the target itself was when the frame was kept.
    std::optional<cv::Point2f> change(const cv::Mat& color, double threshold, int minima) noexcept;

  private:
    cv::Mat frame_;
};

}  // namespace raypoint::core::detail
