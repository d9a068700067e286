// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "raypoint/core/estimator.hpp"
#include "raypoint/core/ray_caster.hpp"

namespace raypoint::core::detail {

class RayEstimatorBase : public Estimator {
  public:
    explicit RayEstimatorBase(const EstimatorSettings& settings);
    const EstimatorTrace& trace() const noexcept override { return trace_; }

  protected:
    cv::Point2f relocate(const cv::Mat& edges, cv::Point2f inner) noexcept;

    EstimatorSettings settings_;
    RayCaster caster_;
    std::vector<RayHit> hits_;
    std::vector<RayHit> scratch_;
    std::vector<RayHit> relocation_;
    EstimatorTrace trace_;
};

class RayEstimator final : public RayEstimatorBase {
  public:
    using RayEstimatorBase::RayEstimatorBase;
    Estimate estimate(const cv::Mat& edges, cv::Point2f inner) noexcept override;
};

class IterativeRayEstimator final : public RayEstimatorBase {
  public:
    using RayEstimatorBase::RayEstimatorBase;
    Estimate estimate(const cv::Mat& edges, cv::Point2f inner) noexcept override;
};

class IterativeNyRayEstimator final : public RayEstimatorBase {
  public:
    using RayEstimatorBase::RayEstimatorBase;
    Estimate estimate(const cv::Mat& edges, cv::Point2f inner) noexcept override;
};

}  // namespace raypoint::core::detail
