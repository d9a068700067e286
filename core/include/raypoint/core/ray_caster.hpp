// SPDX-License-Identifier: MIT
#pragma once
// Ray casting on a binary edge image: the primitive under all four estimators (paper 3.1-3.4).

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
    // ray. `visit(x, y)` is called for every pixel a ray runs through, origin included.
    template <typename Visit>
    void cast(const cv::Mat& edges, cv::Point2f origin, std::vector<RayHit>& hits,
              Visit&& visit) const noexcept;

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
    // Steps from `from` (the last pixel before an edge) along `d` to the edge band's ridge; 0
    // when there is no edge ahead (the ray left the image).
    static float ridge_steps(const cv::Mat& edges, cv::Point2f from, cv::Point2f d) noexcept;

    // Unit steps along the major axis: each step enters exactly one new row or column.
    std::vector<cv::Point2f> directions_;
    std::vector<float> step_lengths_;
};

template <typename Visit>
void RayCaster::cast(const cv::Mat& edges, cv::Point2f origin, std::vector<RayHit>& hits,
                     Visit&& visit) const noexcept {
    const int width = edges.cols;
    const int height = edges.rows;
    const int origin_x = cvRound(origin.x);
    const int origin_y = cvRound(origin.y);
    const bool origin_inside = origin_x >= 0 && origin_y >= 0 && origin_x < width &&
                               origin_y < height &&
                               edges.ptr<std::uint8_t>(origin_y)[origin_x] == 0;
    if (origin_inside) visit(origin_x, origin_y);
    for (std::size_t r = 0; r < directions_.size(); ++r) {
        if (!origin_inside) {
            hits.push_back({origin, 0.0F});
            continue;
        }
        const cv::Point2f d = directions_[r];
        cv::Point2f position = origin;
        int steps = 0;
        for (;;) {
            const cv::Point2f next = position + d;
            const int x = cvRound(next.x);
            const int y = cvRound(next.y);
            if (x < 0 || y < 0 || x >= width || y >= height || edges.ptr<std::uint8_t>(y)[x] != 0) {
                break;
            }
            visit(x, y);
            position = next;
            ++steps;
        }
        const float ridge = ridge_steps(edges, position, d);
        hits.push_back({position, (static_cast<float>(steps) + ridge) * step_lengths_[r]});
    }
}

inline float RayCaster::ridge_steps(const cv::Mat& edges, cv::Point2f from,
                                    cv::Point2f d) noexcept {
    // An edge band is a few pixels wide; past this the ray has met another structure.
    constexpr int band_limit = 4;
    int strongest = 0;
    int first_strongest = 0;
    int last_strongest = 0;
    int previous = 0;
    cv::Point2f position = from;
    for (int k = 1; k <= band_limit; ++k) {
        position += d;
        const int x = cvRound(position.x);
        const int y = cvRound(position.y);
        if (x < 0 || y < 0 || x >= edges.cols || y >= edges.rows) break;
        const int strength = edges.ptr<std::uint8_t>(y)[x];
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
