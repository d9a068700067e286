// SPDX-License-Identifier: MIT
#include "estimator_common.hpp"

namespace raypoint::core::detail {

cv::Point2f mean_point(const std::vector<RayHit>& hits) noexcept {
    if (hits.empty()) return {};
    double x = 0.0;
    double y = 0.0;
    for (const auto& hit : hits) {
        x += hit.point.x;
        y += hit.point.y;
    }
    const auto n = static_cast<double>(hits.size());
    return {static_cast<float>(x / n), static_cast<float>(y / n)};
}

double fan_area(const RayHit* hits, int rays) noexcept {
    double sum = 0.0;
    for (int k = 0; k < rays; ++k)
        sum += static_cast<double>(hits[k].length) * hits[k].length;
    return 0.5 * sum * (2.0 * M_PI / rays);
}

double mean_fan_area(const std::vector<RayHit>& hits, int rays) noexcept {
    const std::size_t origins = hits.size() / static_cast<std::size_t>(rays);
    if (origins == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t o = 0; o < origins; ++o)
        sum += fan_area(&hits[o * rays], rays);
    return sum / static_cast<double>(origins);
}

}  // namespace raypoint::core::detail
