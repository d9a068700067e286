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
    // Where the change is, when |color - kept| (the largest of the three channels' differences
    // a pixel, less the paper's brightness offset: the largest of the `minima` smallest
    // distinct values, 4.1) sums to more than `threshold`; nothing without a kept frame of
    // `color`'s size and type. Every pixel over the offset counts: the change is the target's
    // whole projection, not a moving outline, and the strongest half of it can be a few pixels
    // where the target itself was when the frame was kept. The point is the changed pixel
    // deepest inside the change (farthest from any unchanged pixel; of equals, the one nearest
    // the change's centre of mass): a hand's palm, where its centre of mass can fall between
    // the fingers or on a thumb's root that the scenery's edges crowd, and a disk's centre.
    std::optional<cv::Point2f> change(const cv::Mat& color, double threshold, int minima) noexcept;

  private:
    // The changed pixel farthest from any unchanged one (3-4 chamfer distance; outside the
    // frame counts as unchanged), of equals the nearest to `centre`.
    cv::Point deepest(int offset, cv::Point2f centre) noexcept;

    cv::Mat frame_;
    cv::Mat difference_;  // CV_8U: each pixel's largest channel difference, this change
    cv::Mat depth_;       // CV_16U: each changed pixel's chamfer distance from the unchanged
};

}  // namespace raypoint::core::detail
