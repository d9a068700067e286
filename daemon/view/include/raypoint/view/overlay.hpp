// SPDX-License-Identifier: MIT
#pragma once
// The tracker's view drawn over a frame: the edge or difference image, the selected blocks, the
// rays, the inner point, the centroid and, on a frame that ran RECOVERING, the recovery points.
// Markers use pure colours that appear nowhere else in the overlay, so a test finds them.

#include <opencv2/core.hpp>

#include "raypoint/core/tracker.hpp"

namespace raypoint::view {

// What lies under the markers: the edge pixels (edge_threshold applies) or the compensated
// difference image that picks the target and measures movement.
enum class BackgroundView { edges, difference };

inline const cv::Scalar overlay_edge_color{0, 200, 0};
inline const cv::Scalar overlay_block_color{255, 128, 0};
inline const cv::Scalar overlay_ray_color{0, 255, 255};
inline const cv::Scalar overlay_inner_color{255, 255, 0};
inline const cv::Scalar overlay_centroid_color{255, 0, 255};  // drawn last, never blended
inline const cv::Scalar overlay_recovery_color{0, 128, 255};
constexpr int centroid_marker_size = 18;  // pixels across, a cross 2 pixels thick

// Draws onto `frame` (BGR, the input size) in place. `edge_threshold` draws the edges at that
// threshold (the tracker's own, or one being tuned on a paused frame).
void draw_tracker_view(cv::Mat& frame, const core::Tracker& tracker,
                       const core::FrameResult& result, BackgroundView view, int edge_threshold);

}  // namespace raypoint::view
