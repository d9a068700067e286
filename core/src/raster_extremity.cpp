// SPDX-License-Identifier: MIT
// The raster estimator's far end of a region that crosses the image border
// (EstimatorSettings::extremity): where a limb enters the picture, and what points.
#include "raster_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace raypoint::core::detail {

// Positions round the border clockwise from the top-left corner: the top row left to right,
// the right column down, the bottom row right to left, the left column up; a corner pixel
// takes the first side it is on. 2 (w - 1) + 2 (h - 1) positions.
int RasterEstimator::perimeter_position(cv::Point pixel) const noexcept {
    const int right = width_ - 1;
    const int bottom = height_ - 1;
    if (pixel.y == 0) return pixel.x;
    if (pixel.x == right) return right + pixel.y;
    if (pixel.y == bottom) return right + bottom + (right - pixel.x);
    return 2 * right + bottom + (bottom - pixel.y);
}

// A limb entering the picture meets the border in one run of pixels as wide as the limb; the
// fingertips of a hand reaching past the top, or a region hugging the border, meet it in short
// runs with gaps between them. The run may wrap round the starting corner. The region is
// queue_'s first inside_count pixels; on_border_ marks its border pixels' positions.
RasterEstimator::BorderContact RasterEstimator::border_contact(std::size_t inside_count) noexcept {
    BorderContact contact;
    if (width_ < 2 || height_ < 2) return contact;
    const int perimeter = 2 * (width_ - 1) + 2 * (height_ - 1);
    std::fill(on_border_.begin(), on_border_.begin() + perimeter, 0);
    // On the border: not x - 1 < w - 2 and y - 1 < h - 2, unsigned.
    const auto inner_w = static_cast<unsigned>(width_ - 2);
    const auto inner_h = static_cast<unsigned>(height_ - 2);
    for (std::size_t i = 0; i < inside_count; ++i) {
        const cv::Point p = queue_[i];
        if (static_cast<unsigned>(p.x - 1) >= inner_w ||
            static_cast<unsigned>(p.y - 1) >= inner_h) {
            on_border_[static_cast<std::size_t>(perimeter_position(p))] = 1;
            ++contact.pixels;
            contact.centre.x += p.x;
            contact.centre.y += p.y;
        }
    }
    if (contact.pixels == 0) return contact;
    contact.centre *= 1.0 / contact.pixels;
    // Start the walk just after a position not reached, so that no run is split by the wrap.
    int start = 0;
    while (start < perimeter && on_border_[static_cast<std::size_t>(start)] != 0)
        ++start;
    if (start == perimeter) {
        contact.longest_run = perimeter;
        return contact;
    }
    int run = 0;
    for (int k = 1; k <= perimeter; ++k) {
        if (on_border_[static_cast<std::size_t>((start + k) % perimeter)] != 0) {
            contact.longest_run = std::max(contact.longest_run, ++run);
        } else {
            run = 0;
        }
    }
    return contact;
}

// A region that runs over the image border is a limb, or a body, coming in from outside the
// picture: what points is its far end (the hand at the end of an arm, the ball a hand holds up).
// A limb crosses the border in one run at least `extremity_contact` pixels long that holds at
// least half of the region's border pixels. The region's pixels beyond `extremity` of the
// farthest one's distance from where it crosses (the border pixels' centre) are that end; its
// inner point is the one of them nearest their centroid.
void RasterEstimator::keep_extremity(Estimate& estimate, std::size_t inside_count) noexcept {
    const BorderContact contact = border_contact(inside_count);
    if (contact.longest_run < settings_.extremity_contact ||
        2 * contact.longest_run < contact.pixels) {
        return;
    }
    const cv::Point2d base = contact.centre;
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
