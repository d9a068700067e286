// SPDX-License-Identifier: MIT
#include "raypoint/core/ray_caster.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

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
    const int steps = static_cast<int>(std::floor(major));
    const cv::Point2f d = major > 0.0F ? delta / major : cv::Point2f();
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

cv::Point2f RayCaster::off_edge(const cv::Mat& edges, cv::Point2f point, int radius) noexcept {
    const int cx = cvRound(point.x);
    const int cy = cvRound(point.y);
    const auto open = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < edges.cols && y < edges.rows &&
               edges.ptr<std::uint8_t>(y)[x] == 0;
    };
    const bool inside_image = cx >= 0 && cy >= 0 && cx < edges.cols && cy < edges.rows;
    if (!inside_image || open(cx, cy)) return point;
    std::optional<cv::Point> best;
    int best_distance = 0;
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            const int distance = dx * dx + dy * dy;
            if (distance > radius * radius || !open(cx + dx, cy + dy)) continue;
            if (!best || distance < best_distance) {
                best = cv::Point(cx + dx, cy + dy);
                best_distance = distance;
            }
        }
    }
    return best ? cv::Point2f(static_cast<float>(best->x), static_cast<float>(best->y)) : point;
}

}  // namespace raypoint::core
