#include "raypoint/core/ray_caster.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {

RayCaster::RayCaster(int rays) {
    directions_.reserve(static_cast<std::size_t>(rays));
    step_lengths_.reserve(static_cast<std::size_t>(rays));
    for (int k = 0; k < rays; ++k) {
        const double angle = 2.0 * M_PI * k / rays;
        const double c = std::cos(angle);
        const double s = std::sin(angle);
        const double major = std::max(std::abs(c), std::abs(s));
        directions_.emplace_back(static_cast<float>(c / major), static_cast<float>(s / major));
        step_lengths_.push_back(static_cast<float>(1.0 / major));
    }
}

cv::Point2f RayCaster::walk(const cv::Mat& edges, cv::Point2f from, cv::Point2f to) noexcept {
    const cv::Point2f delta = to - from;
    const float major = std::max(std::abs(delta.x), std::abs(delta.y));
    if (major < 1.0F) return to;
    const int steps = static_cast<int>(std::floor(major));
    const cv::Point2f d = delta / major;
    cv::Point2f position = from;
    for (int i = 1; i <= steps; ++i) {
        const cv::Point2f next = from + d * static_cast<float>(i);
        const int x = cvRound(next.x);
        const int y = cvRound(next.y);
        if (x < 0 || y < 0 || x >= edges.cols || y >= edges.rows ||
            edges.ptr<std::uint8_t>(y)[x] != 0) {
            return position;
        }
        position = next;
    }
    // The remaining fraction of a step lands on `to` itself, which is checked like any step.
    const int x = cvRound(to.x);
    const int y = cvRound(to.y);
    if (x < 0 || y < 0 || x >= edges.cols || y >= edges.rows ||
        edges.ptr<std::uint8_t>(y)[x] != 0) {
        return position;
    }
    return to;
}

}  // namespace raypoint::core
