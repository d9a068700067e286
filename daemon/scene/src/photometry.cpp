// SPDX-License-Identifier: MIT
#include "photometry.hpp"

#include <cmath>

#include "rng.hpp"

namespace raypoint::scene {
namespace {

constexpr int slack = 47;  // offsets per axis: 47 x 47 distinct noise frames
constexpr double corner_light = 0.85;

}  // namespace

cv::Mat make_vignette(cv::Size size) {
    cv::Mat v(size, CV_32F);
    const double cx = size.width / 2.0;
    const double cy = size.height / 2.0;
    const double r2_corner = cx * cx + cy * cy;
    for (int y = 0; y < size.height; ++y) {
        auto* row = v.ptr<float>(y);
        for (int x = 0; x < size.width; ++x) {
            const double dx = x + 0.5 - cx;
            const double dy = y + 0.5 - cy;
            row[x] = static_cast<float>(1 - (1 - corner_light) * (dx * dx + dy * dy) / r2_corner);
        }
    }
    return v;
}

double exposure_gain(const SceneSpec& spec, double t) {
    int jumps = 0;
    for (const double when : spec.brightness_jumps)
        jumps += when <= t ? 1 : 0;
    const double level = jumps % 2 == 1 ? 1 / (1 + spec.brightness_jump) : 1.0;
    return spec.darkness * level;
}

cv::Vec3d drift_gains(const SceneSpec& spec, double t) {
    const double phase = 2 * CV_PI * t / spec.drift_period;
    const double exposure = 1 + spec.exposure_drift * std::sin(phase);
    const double wb = spec.white_balance_drift;
    return {exposure * (1 + wb * std::sin(phase + 1.3)),
            exposure * (1 + 0.3 * wb * std::sin(phase)),
            exposure * (1 - wb * std::sin(phase + 1.3))};
}

double flicker_gain(const SceneSpec& spec, double t, int y, int rows) {
    if (spec.flicker_depth <= 0) return 1.0;
    const double read_at = t + spec.readout_seconds * y / rows;
    return 1 + spec.flicker_depth * std::sin(2 * CV_PI * spec.flicker_hz * read_at);
}

NoisePool::NoisePool(cv::Size size, double sigma, std::uint64_t seed) : size_(size), seed_(seed) {
    if (sigma <= 0) return;
    field_.create(size.height + slack, size.width + slack, CV_32FC3);
    cv::RNG rng(mix_seed(seed, 3));
    rng.fill(field_, cv::RNG::NORMAL, 0, sigma);
}

cv::Point NoisePool::offset(int index) const {
    Rng rng(mix_seed(seed_, 1000 + static_cast<std::uint64_t>(index)));
    // Even x offsets for even frames, odd for odd ones: neighbours always differ.
    return {2 * rng.integer(0, slack / 2 - 1) + index % 2, rng.integer(0, slack - 1)};
}

cv::Mat NoisePool::frame_noise(int index) const {
    return field_(cv::Rect(offset(index), size_));
}

}  // namespace raypoint::scene
