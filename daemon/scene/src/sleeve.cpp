// SPDX-License-Identifier: MIT
#include "sleeve.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace raypoint::scene {
namespace {

constexpr double cuff = 1.2;         // the sleeve's half width over the wrist's
constexpr double fold_period = 1.6;  // folds along the arm, in sleeve radii
constexpr double fold_depth = 0.06;  // how much darker a fold's bottom is
constexpr double rim_light = 0.78;   // light at the sleeve's sides, 1 along its middle

}  // namespace

Sleeve::Sleeve(const Placement& hand, cv::Size frame)
    : frame_(frame),
      start_(hand.to_frame(hand.sprite().wrist)),
      axis_(hand.down()),
      length_(2.0 * (frame.width + frame.height)),
      radius_(cuff * hand.sprite().wrist_radius * hand.px_per_unit()) {}

cv::Rect Sleeve::bounds() const {
    const cv::Point2d end = start_ + axis_ * length_;
    const double r = radius_ + 2;
    const cv::Rect box(cv::Point(static_cast<int>(std::floor(std::min(start_.x, end.x) - r)),
                                 static_cast<int>(std::floor(std::min(start_.y, end.y) - r))),
                       cv::Point(static_cast<int>(std::ceil(std::max(start_.x, end.x) + r)),
                                 static_cast<int>(std::ceil(std::max(start_.y, end.y) + r))));
    return box & cv::Rect(0, 0, frame_.width, frame_.height);
}

std::pair<int, int> Sleeve::row_span(int y, double reach, cv::Rect roi) const {
    // The part of the axis within `reach` of the row's centre line, widened by `reach`.
    const double centre = y + 0.5;
    double t0 = 0;
    double t1 = length_;
    if (std::abs(axis_.y) > 1e-9) {
        const double a = (centre - reach - start_.y) / axis_.y;
        const double b = (centre + reach - start_.y) / axis_.y;
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    } else if (std::abs(centre - start_.y) > reach) {
        return {0, 0};
    }
    if (t0 > t1) return {0, 0};
    const double x0 = start_.x + axis_.x * t0;
    const double x1 = start_.x + axis_.x * t1;
    const int first = std::max(roi.x, static_cast<int>(std::floor(std::min(x0, x1) - reach)));
    const int last = std::min(roi.br().x, static_cast<int>(std::ceil(std::max(x0, x1) + reach)));
    return {first, std::max(first, last)};
}

void Sleeve::add_coverage(cv::Rect roi, float weight, cv::Mat& acc) const {
    for (int y = roi.y; y < roi.br().y; ++y) {
        const auto [first, last] = row_span(y, radius_ + 1, roi);
        auto* a = acc.ptr<float>(y - roi.y);
        for (int x = first; x < last; ++x) {
            const cv::Point2d p(x + 0.5 - start_.x, y + 0.5 - start_.y);
            const double along = std::clamp(p.dot(axis_), 0.0, length_);
            const double distance = cv::norm(p - axis_ * along) - radius_;
            a[x - roi.x] += weight * static_cast<float>(std::clamp(0.5 - distance, 0.0, 1.0));
        }
    }
}

cv::Mat Sleeve::colour(cv::Rect roi, const Colour& cloth) const {
    cv::Mat out(roi.size(), CV_32FC3);
    const double pi = 3.141592653589793;
    for (int y = roi.y; y < roi.br().y; ++y) {
        auto* row = out.ptr<cv::Vec3f>(y - roi.y);
        for (int x = roi.x; x < roi.br().x; ++x) {
            const cv::Point2d p(x + 0.5 - start_.x, y + 0.5 - start_.y);
            const double along = p.dot(axis_);
            const double across = std::min(1.0, std::abs(p.cross(axis_)) / radius_);
            const double cylinder = rim_light + (1 - rim_light) * std::sqrt(1 - across * across);
            const double fold = 0.5 + 0.5 * std::sin(2 * pi * along / (fold_period * radius_));
            const auto light = static_cast<float>(cylinder * (1 - fold_depth * fold * fold));
            row[x - roi.x] = cv::Vec3f(static_cast<float>(cloth.b), static_cast<float>(cloth.g),
                                       static_cast<float>(cloth.r)) *
                             light;
        }
    }
    return out;
}

}  // namespace raypoint::scene
