// SPDX-License-Identifier: MIT
#include "passer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "motion_blur.hpp"

namespace raypoint::scene {

Passer::Passer(cv::Size frame, const SceneSpec& spec)
    : frame_(frame),
      starts_(spec.passes),
      seconds_(spec.pass_seconds),
      radius_(0.5 * spec.pass_size * frame.height),
      y_(spec.pass_y * frame.height) {
    const Colour c = spec.pass_colour.value_or(Colour{60, 60, 60});
    colour_ = cv::Vec3f(static_cast<float>(c.b), static_cast<float>(c.g), static_cast<float>(c.r));
}

void Passer::draw(double t, double exposure, const cv::Mat& vignette, cv::Mat& light) const {
    // From fully beyond one side to fully beyond the other: even passes go right to left (the
    // way the targets enter), odd ones back.
    const double travel = frame_.width + 2 * radius_;
    const double speed = travel / seconds_;  // pixels a second
    for (std::size_t i = 0; i < starts_.size(); ++i) {
        const double u = t - starts_[i];
        if (u < -exposure || u > seconds_ + exposure) continue;
        const double dir = i % 2 == 0 ? -1.0 : 1.0;
        const double x0 = dir < 0 ? frame_.width + radius_ : -radius_;
        const int subs = sub_frame_count(speed * exposure);
        std::array<double, max_sub_frames> positions{};
        const auto xs = std::span<const double>(positions.data(), static_cast<std::size_t>(subs));
        for (int k = 0; k < subs; ++k) {
            const double when = subs == 1 ? u : u - exposure / 2 + exposure * (k + 0.5) / subs;
            positions[static_cast<std::size_t>(k)] =
                x0 + dir * speed * std::clamp(when, 0.0, seconds_);
        }
        const double lo = *std::min_element(xs.begin(), xs.end()) - radius_ - 1;
        const double hi = *std::max_element(xs.begin(), xs.end()) + radius_ + 1;
        const cv::Rect box = cv::Rect(cv::Point(static_cast<int>(std::floor(lo)),
                                                static_cast<int>(std::floor(y_ - radius_ - 1))),
                                      cv::Point(static_cast<int>(std::ceil(hi)),
                                                static_cast<int>(std::ceil(y_ + radius_ + 1)))) &
                             cv::Rect(0, 0, frame_.width, frame_.height);
        const auto weight = static_cast<float>(1.0 / subs);
        for (int y = box.y; y < box.br().y; ++y) {
            const auto* v = vignette.ptr<float>(y);
            auto* out = light.ptr<cv::Vec3f>(y);
            const double dy = y + 0.5 - y_;
            for (int x = box.x; x < box.br().x; ++x) {
                // Coverage of the pixel: a one-pixel ramp across the outline, averaged over
                // the sub-positions; shading: matte, darker toward the rim.
                float cover = 0;
                float shade = 0;
                for (const double cx : xs) {
                    const double dx = x + 0.5 - cx;
                    const double r = std::sqrt(dx * dx + dy * dy);
                    const auto c = static_cast<float>(std::clamp(radius_ + 0.5 - r, 0.0, 1.0));
                    if (c <= 0) continue;
                    const double rim = std::min(1.0, r / radius_);
                    cover += weight * c;
                    shade += weight * c * static_cast<float>(1.1 - 0.35 * rim * rim);
                }
                if (cover <= 0) continue;
                const cv::Vec3f ball = colour_ * (shade / cover * v[x]);
                out[x] += cover * (ball - out[x]);
            }
        }
    }
}

}  // namespace raypoint::scene
