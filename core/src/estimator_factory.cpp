// SPDX-License-Identifier: MIT
#include "raster_estimator.hpp"
#include "ray_estimators.hpp"

namespace raypoint::core {

std::unique_ptr<Estimator> make_estimator(const EstimatorSettings& settings) {
    switch (settings.kind) {
        case EstimatorKind::ray:
            return std::make_unique<detail::RayEstimator>(settings);
        case EstimatorKind::iterative_ray:
            return std::make_unique<detail::IterativeRayEstimator>(settings);
        case EstimatorKind::iterative_ny_ray:
            return std::make_unique<detail::IterativeNyRayEstimator>(settings);
        case EstimatorKind::raster:
            return std::make_unique<detail::RasterEstimator>(settings);
    }
    return nullptr;
}

std::string_view to_string(EstimatorKind kind) noexcept {
    for (const auto& [k, name] : estimator_names) {
        if (k == kind) return name;
    }
    return "?";
}

bool estimator_from_string(std::string_view name, EstimatorKind& kind) noexcept {
    for (const auto& [k, known] : estimator_names) {
        if (known == name) {
            kind = k;
            return true;
        }
    }
    return false;
}

}  // namespace raypoint::core
