// SPDX-License-Identifier: MIT
// The raster estimator's far end of a region that crosses the image border
// (EstimatorSettings::extremity): where a limb enters the picture, and what points.
#include "raster_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace raypoint::core::detail {

// A region that runs over the image border is a limb, or a body, coming in from outside the
// picture: what points is its far end (the hand at the end of an arm, the ball a hand holds up).
// The region's pixels beyond `extremity` of the farthest one's distance from where it crosses
// the border are that end; its inner point is the one of them nearest their centroid.
void RasterEstimator::keep_extremity(Estimate& estimate, std::size_t inside_count) const noexcept {
    double contact = 0.0;
    double contact_x = 0.0;
    double contact_y = 0.0;
    // On the border: not x - 1 < w - 2 and y - 1 < h - 2, unsigned.
    const auto inner_w = static_cast<unsigned>(std::max(width_ - 2, 0));
    const auto inner_h = static_cast<unsigned>(std::max(height_ - 2, 0));
    for (std::size_t i = 0; i < inside_count; ++i) {
        const cv::Point p = queue_[i];
        if (static_cast<unsigned>(p.x - 1) >= inner_w ||
            static_cast<unsigned>(p.y - 1) >= inner_h) {
            contact += 1.0;
            contact_x += p.x;
            contact_y += p.y;
        }
    }
    if (contact < settings_.extremity_contact) return;
    const cv::Point2d base(contact_x / contact, contact_y / contact);
    const auto distance = [&](cv::Point p) { return std::hypot(p.x - base.x, p.y - base.y); };
    double farthest = 0.0;
    for (std::size_t i = 0; i < inside_count; ++i)
        farthest = std::max(farthest, distance(queue_[i]));
    const double reach = settings_.extremity * farthest;
    double area = 0.0;
    double sum_x = 0.0;
    double sum_y = 0.0;
    for (std::size_t i = 0; i < inside_count; ++i) {
        if (distance(queue_[i]) < reach) continue;
        area += 1.0;
        sum_x += queue_[i].x;
        sum_y += queue_[i].y;
    }
    if (area <= 0.0) return;
    const cv::Point2f centroid(static_cast<float>(sum_x / area), static_cast<float>(sum_y / area));
    cv::Point2f inner = estimate.inner;
    double nearest = -1.0;
    for (std::size_t i = 0; i < inside_count; ++i) {
        const cv::Point p = queue_[i];
        if (distance(p) < reach) continue;
        const double d = std::hypot(p.x - static_cast<double>(centroid.x),
                                    p.y - static_cast<double>(centroid.y));
        if (nearest < 0.0 || d < nearest) {
            nearest = d;
            inner = cv::Point2f(static_cast<float>(p.x), static_cast<float>(p.y));
        }
    }
    // The part's share of the region's outline band is not known: its area is the inside pixels,
    // scaled by the whole region's band-to-inside ratio.
    estimate.crosses_border = true;
    estimate.end_area = area * estimate.area / static_cast<double>(inside_count);
    estimate.end_centroid = centroid;
    estimate.end_inner = inner;
}

}  // namespace raypoint::core::detail
