// SPDX-License-Identifier: MIT
// The three estimators without rasterization (paper 3.1, 3.2, 3.3).

#include "ray_estimators.hpp"
#include "estimator_common.hpp"

namespace raypoint::core::detail {
namespace {

constexpr auto no_visit = [](int, int) {};

}  // namespace

RayEstimatorBase::RayEstimatorBase(const EstimatorSettings& settings)
    : settings_(settings), caster_(settings.rays) {
    const auto rays = static_cast<std::size_t>(settings.rays);
    std::size_t last_level = 1;
    for (int level = 0; level < settings.recasts; ++level)
        last_level *= rays;
    hits_.reserve(last_level);
    scratch_.reserve(last_level);
    relocation_.reserve(rays);
    trace_.rays.reserve(2 * last_level + rays);
}

// Rays from the inner point, then the inner point to the mean of their hits: "in order to
// center it in the projection area it is located". A walk, so it never jumps across an edge.
cv::Point2f RayEstimatorBase::relocate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    relocation_.clear();
    caster_.cast(edges, inner, relocation_);
    for (const auto& hit : relocation_)
        trace_.rays.push_back({inner, hit.point});
    return RayCaster::walk(edges, inner, mean_point(relocation_));
}

// Paper 3.1: one cast; centroid = mean hit; inner point walks toward it and is recentred.
Estimate RayEstimator::estimate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    inner = RayCaster::off_edge(edges, inner, settings_.edge_escape);
    trace_.rays.clear();
    cast_levels(caster_, edges, inner, 1, hits_, scratch_, &trace_.rays, no_visit);
    Estimate result;
    result.centroid = mean_point(hits_);
    result.area = mean_fan_area(hits_, settings_.rays);
    result.inner = relocate(edges, RayCaster::walk(edges, inner, result.centroid));
    result.iterations = 1;
    return result;
}

// Paper 3.2: cast, centroid, walk, repeated until both stop moving; the inner point is
// recentred once, after the loop.
Estimate IterativeRayEstimator::estimate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    inner = RayCaster::off_edge(edges, inner, settings_.edge_escape);
    Estimate result;
    Convergence convergence(settings_.tolerance);
    for (int i = 0; i < settings_.max_iterations; ++i) {
        trace_.rays.clear();
        cast_levels(caster_, edges, inner, 1, hits_, scratch_, &trace_.rays, no_visit);
        result.centroid = mean_point(hits_);
        result.area = mean_fan_area(hits_, settings_.rays);
        const cv::Point2f moved = RayCaster::walk(edges, inner, result.centroid);
        result.iterations = i + 1;
        const bool settled = convergence.settled(result.centroid, inner, moved);
        inner = moved;
        if (settled) break;
    }
    result.inner = relocate(edges, inner);
    return result;
}

// Paper 3.3: y levels of casting, centroid = mean of the n^y last hits, walk, recentre, repeat.
Estimate IterativeNyRayEstimator::estimate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    inner = RayCaster::off_edge(edges, inner, settings_.edge_escape);
    Estimate result;
    Convergence convergence(settings_.tolerance);
    for (int i = 0; i < settings_.max_iterations; ++i) {
        trace_.rays.clear();
        cast_levels(caster_, edges, inner, settings_.recasts, hits_, scratch_, &trace_.rays,
                    no_visit);
        result.centroid = mean_point(hits_);
        result.area = mean_fan_area(hits_, settings_.rays);
        const cv::Point2f moved = relocate(edges, RayCaster::walk(edges, inner, result.centroid));
        result.iterations = i + 1;
        const bool settled = convergence.settled(result.centroid, inner, moved);
        inner = moved;
        if (settled) break;
    }
    result.inner = inner;
    return result;
}

}  // namespace raypoint::core::detail
