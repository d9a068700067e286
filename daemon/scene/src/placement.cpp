// SPDX-License-Identifier: MIT
#include "placement.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace raypoint::scene {

Placement::Placement(const Sprite& sprite, const Camera& camera, double size_m, const Pose& pose)
    : sprite_(sprite),
      centre_(pose.x * camera.width, pose.y * camera.height),
      px_per_unit_(camera.px_per_metre(pose.depth) * size_m),
      cos_(std::cos(sprite.rotates ? pose.angle : 0.0)),
      sin_(std::sin(sprite.rotates ? pose.angle : 0.0)) {}

std::array<cv::Point2d, 4> Placement::corners() const {
    const cv::Rect2d& e = sprite_.extent;
    const std::array<cv::Point2d, 4> local{
        {{e.x, e.y}, {e.x + e.width, e.y}, {e.x, e.y + e.height}, {e.x + e.width, e.y + e.height}}};
    std::array<cv::Point2d, 4> out{};
    for (std::size_t i = 0; i < local.size(); ++i)
        out[i] = to_frame(local[i]);
    return out;
}

cv::Point2d Placement::to_frame(cv::Point2d units) const {
    const cv::Point2d p = units * px_per_unit_;
    return centre_ + cv::Point2d(cos_ * p.x - sin_ * p.y, sin_ * p.x + cos_ * p.y);
}

cv::Rect Placement::bounds() const {
    double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
    for (const cv::Point2d& c : corners()) {
        x0 = std::min(x0, c.x), y0 = std::min(y0, c.y);
        x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
    }
    // Keep far-away poses from overflowing int; they get clipped to the frame anyway.
    auto clamp = [](double v) { return static_cast<int>(std::clamp(v, -1e6, 1e6)); };
    const int left = clamp(std::floor(x0)) - 2;
    const int top = clamp(std::floor(y0)) - 2;
    return {left, top, clamp(std::ceil(x1)) + 2 - left, clamp(std::ceil(y1)) + 2 - top};
}

cv::Mat Placement::sample(const cv::Mat& texture, cv::Rect roi, int border,
                          double border_value) const {
    // Inverse map: ROI pixel (i, j) has its centre at frame position (roi.x + i + 0.5, ...);
    // rotate that back about the target's centre into units, then into texel coordinates,
    // where OpenCV puts texel k's centre at k.
    const double k = sprite_.texels_per_unit / px_per_unit_;
    const double dx = roi.x + 0.5 - centre_.x;
    const double dy = roi.y + 0.5 - centre_.y;
    const cv::Matx23d to_texture(k * cos_, k * sin_,
                                 k * (cos_ * dx + sin_ * dy) + sprite_.origin.x - 0.5, -k * sin_,
                                 k * cos_, k * (-sin_ * dx + cos_ * dy) + sprite_.origin.y - 0.5);
    cv::Mat out;
    cv::warpAffine(texture, out, to_texture, roi.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                   border, cv::Scalar::all(border_value));
    return out;
}

void Placement::add_coverage(cv::Rect roi, float weight, cv::Mat& acc) const {
    // Outside the texture lies at least one unit from the outline.
    const cv::Mat sdf = sample(sprite_.sdf, roi, cv::BORDER_CONSTANT, 1.0);
    const auto scale = static_cast<float>(px_per_unit_);
    for (int y = 0; y < roi.height; ++y) {
        const auto* d = sdf.ptr<float>(y);
        auto* a = acc.ptr<float>(y);
        for (int x = 0; x < roi.width; ++x) {
            a[x] += weight * std::clamp(0.5f - d[x] * scale, 0.0f, 1.0f);
        }
    }
}

cv::Mat Placement::mask(cv::Rect roi) const {
    const cv::Mat sdf = sample(sprite_.sdf, roi, cv::BORDER_CONSTANT, 1.0);
    cv::Mat m;
    cv::compare(sdf, 0.0, m, cv::CMP_LE);
    return m;
}

cv::Mat Placement::colour(cv::Rect roi) const {
    return sample(sprite_.colour, roi, cv::BORDER_REPLICATE, 0.0);
}

}  // namespace raypoint::scene
