// SPDX-License-Identifier: MIT
#pragma once
// Pieces shared by the four estimators: multi-level casting, means and the ray-fan area.

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/estimator.hpp"
#include "raypoint/core/ray_caster.hpp"

namespace raypoint::core::detail {

cv::Point2f mean_point(const std::vector<RayHit>& hits) noexcept;

// Area seen from one origin through n evenly spaced rays: the fan of sectors sum(L^2/2 * 2pi/n).
// The paper says "the sum of the lengths of the casted rays", which is a length, not an area;
// the fan is the area those lengths describe (docs/estimators.md).
double fan_area(const RayHit* hits, int rays) noexcept;

// Mean fan area over the origins of a level whose hits are stored origin after origin.
double mean_fan_area(const std::vector<RayHit>& hits, int rays) noexcept;

inline float distance(cv::Point2f a, cv::Point2f b) noexcept {
    const cv::Point2f d = a - b;
    return std::sqrt(d.dot(d));
}

// The paper's stopping rule for the iterative estimators: the adjustment of both the centroid
// and the inner point is negligible (under the tolerance, working pixels).
class Convergence {
  public:
    explicit Convergence(double tolerance) noexcept : tolerance_(tolerance) {}
    bool settled(cv::Point2f centroid, cv::Point2f inner_before, cv::Point2f inner_after) noexcept {
        const bool settled = distance(inner_after, inner_before) < tolerance_ &&
                             distance(centroid, previous_centroid_) < tolerance_;
        previous_centroid_ = centroid;
        return settled;
    }

  private:
    double tolerance_;
    cv::Point2f previous_centroid_{-1e6F, -1e6F};  // nothing to compare the first one with
};

// Casts from `origin`, then again from every hit, `levels` times in all (paper 3.3: n^y rays
// in the last level). On return `last` holds the last level's hits, n per origin in order;
// `scratch` is reused storage. Every segment is appended to `rays` when it is not null.
template <typename Visit>
void cast_levels(const RayCaster& caster, const cv::Mat& edges, cv::Point2f origin, int levels,
                 std::vector<RayHit>& last, std::vector<RayHit>& scratch,
                 std::vector<RaySegment>* rays, Visit&& visit) noexcept {
    last.clear();
    caster.cast(edges, origin, last, visit);
    if (rays != nullptr) {
        for (const auto& hit : last)
            rays->push_back({origin, hit.point});
    }
    for (int level = 1; level < levels; ++level) {
        scratch.swap(last);
        last.clear();
        for (const auto& from : scratch) {
            const std::size_t first = last.size();
            caster.cast(edges, from.point, last, visit);
            if (rays != nullptr) {
                for (std::size_t i = first; i < last.size(); ++i) {
                    rays->push_back({from.point, last[i].point});
                }
            }
        }
    }
}

}  // namespace raypoint::core::detail
