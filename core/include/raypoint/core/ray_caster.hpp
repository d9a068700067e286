// SPDX-License-Identifier: MIT
#pragma once
// Ray casting on a binary edge image: the primitive under all four estimators (paper 3.1-3.4).

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <opencv2/core.hpp>

namespace raypoint::core {

// Where a ray stopped: the last pixel before an edge or the image border, so it is still
// inside the region the ray started in, and a ray recast from it can cross that region.
struct RayHit {
    cv::Point2f point;
    // Working pixels from the origin to the outline: through `point` into the edge band up to
    // its ridge (the strongest edge pixel; the middle of a run of equally strong ones), where
    // the outline runs. To `point` itself when the ray left the image.
    float length = 0.0F;
};

class RayCaster {
  public:
    // n rays at angles 2*pi*k/n, k = 0..n-1 (x right, y down).
    explicit RayCaster(int rays);

    int rays() const noexcept { return static_cast<int>(directions_.size()); }

    // Casts all rays from `origin` over `edges` (CV_8U, non-zero = edge) and appends one hit a
    // ray. `visit(x, y)` is called for every pixel a ray runs through, origin included, or
    // `visit(x, y, offset)` when it takes the pixel's byte offset in `edges` (y * step + x). It
    // is taken by value: the copy's captures stay in registers through the steps.
    template <typename Visit>
    void cast(const cv::Mat& edges, cv::Point2f origin, std::vector<RayHit>& hits,
              Visit visit) const noexcept;

    void cast(const cv::Mat& edges, cv::Point2f origin, std::vector<RayHit>& hits) const noexcept {
        cast(edges, origin, hits, [](int, int) {});
    }

    // Moves from `from` toward `to` one pixel at a time and stops at `to` or before the first
    // edge pixel (paper: "displaced towards the new centroid until it reaches it or an edge").
    static cv::Point2f walk(const cv::Mat& edges, cv::Point2f from, cv::Point2f to) noexcept;

    // The non-edge pixel nearest to `point` within `radius` pixels, or `point` itself when it is
    // not on an edge or none is that close. An inner point on an edge casts rays of length 0: it
    // happens when a detection lands on the moving outline or the target moved onto it.
    static cv::Point2f off_edge(const cv::Mat& edges, cv::Point2f point, int radius) noexcept;

  private:
    template <typename Visit>
    static void visit_pixel(Visit& visit, int x, int y, std::size_t offset) noexcept {
        if constexpr (std::is_invocable_v<Visit&, int, int, std::size_t>) {
            visit(x, y, offset);
        } else {
            visit(x, y);
        }
    }

    // Steps along `d` to the edge band's ridge, from the last pixel before the band, the band's
    // first pixel being at `first` (one step on) with edge strength `first_strength` (> 0).
    static float ridge_steps(const std::uint8_t* data, std::size_t stride, unsigned width,
                             unsigned height, cv::Point2f first, int first_strength,
                             cv::Point2f d) noexcept;

    // Unit steps along the major axis: each step enters exactly one new row or column.
    std::vector<cv::Point2f> directions_;
    std::vector<float> step_lengths_;
};

template <typename Visit>
void RayCaster::cast(const cv::Mat& edges, cv::Point2f origin, std::vector<RayHit>& hits,
                     Visit visit) const noexcept {
    // Everything the steps read is local: `visit` may store through a byte pointer, which could
    // alias any member and would have them reloaded at every step.
    const auto width = static_cast<unsigned>(edges.cols);
    const auto height = static_cast<unsigned>(edges.rows);
    const std::uint8_t* const data = edges.data;
    const std::size_t stride = edges.step[0];
    const int origin_x = cvRound(origin.x);
    const int origin_y = cvRound(origin.y);
    // One unsigned comparison an axis: negative coordinates wrap to large ones.
    const bool origin_inside = static_cast<unsigned>(origin_x) < width &&
                               static_cast<unsigned>(origin_y) < height &&
                               data[static_cast<std::size_t>(origin_y) * stride + origin_x] == 0;
    if (!origin_inside) {
        for (std::size_t r = 0; r < directions_.size(); ++r)
            hits.push_back({origin, 0.0F});
        return;
    }
    visit_pixel(visit, origin_x, origin_y, static_cast<std::size_t>(origin_y) * stride + origin_x);
    const cv::Point2f* const directions = directions_.data();
    const float* const step_lengths = step_lengths_.data();
    const std::size_t rays = directions_.size();
    for (std::size_t r = 0; r < rays; ++r) {
        // Float positions stepped by adding d and rounded at each step, as cv::Point2f's +
        // does: the pixels a ray visits depend on those roundings.
        const cv::Point2f d = directions[r];
        cv::Point2f position = origin;
        cv::Point2f next;  // where the ray stopped: an edge pixel, or outside the image
        int steps = 0;
        int strength = 0;  // stays 0 when the ray leaves the image
        for (;;) {
            next = position + d;
            const auto x = static_cast<unsigned>(cvRound(next.x));
            const auto y = static_cast<unsigned>(cvRound(next.y));
            if (x >= width || y >= height) break;
            const std::size_t offset = std::size_t{y} * stride + x;
            strength = data[offset];
            if (strength != 0) break;
            visit_pixel(visit, static_cast<int>(x), static_cast<int>(y), offset);
            position = next;
            ++steps;
        }
        // No edge ahead (the ray left the image): the hit is the last pixel itself.
        const float ridge =
            strength == 0 ? 0.0F : ridge_steps(data, stride, width, height, next, strength, d);
        hits.push_back({position, (static_cast<float>(steps) + ridge) * step_lengths[r]});
    }
}

inline float RayCaster::ridge_steps(const std::uint8_t* data, std::size_t stride, unsigned width,
                                    unsigned height, cv::Point2f first, int first_strength,
                                    cv::Point2f d) noexcept {
    // An edge band is a few pixels wide; past this the ray has met another structure.
    constexpr int band_limit = 4;
    int strongest = first_strength;
    int first_strongest = 1;
    int last_strongest = 1;
    int previous = first_strength;
    float px = first.x;
    float py = first.y;
    for (int k = 2; k <= band_limit; ++k) {
        px += d.x;
        py += d.y;
        const int x = cvRound(px);
        const int y = cvRound(py);
        if (static_cast<unsigned>(x) >= width || static_cast<unsigned>(y) >= height) break;
        const int strength = data[static_cast<std::size_t>(y) * stride + x];
        if (strength == 0 || strength < previous) break;  // out of the band, or past the ridge
        if (strength > strongest) {
            strongest = strength;
            first_strongest = last_strongest = k;
        } else if (strength == strongest) {
            last_strongest = k;
        }
        previous = strength;
    }
    return 0.5F * static_cast<float>(first_strongest + last_strongest);
}

}  // namespace raypoint::core
