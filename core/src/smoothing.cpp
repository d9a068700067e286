// SPDX-License-Identifier: MIT
#include "raypoint/core/smoothing.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {
namespace {

// Smoothing factor of a first-order low-pass with cutoff `hz` sampled every `seconds`.
double alpha(double hz, double seconds) noexcept {
    const double tau = 1.0 / (2.0 * M_PI * hz);
    return 1.0 / (1.0 + tau / seconds);
}

}  // namespace

OneEuroFilter::OneEuroFilter(double min_cutoff_hz, double beta,
                             double derivative_cutoff_hz) noexcept
    : min_cutoff_(min_cutoff_hz), beta_(beta), derivative_cutoff_(derivative_cutoff_hz) {}

void OneEuroFilter::reset(double value, Timestamp timestamp) noexcept {
    value_ = value;
    derivative_ = 0.0;
    last_ = timestamp;
}

double OneEuroFilter::update(double value, Timestamp timestamp) noexcept {
    const double seconds = static_cast<double>(timestamp - last_) * 1e-6;
    if (seconds <= 0.0) return value_;  // a repeated timestamp carries no new information
    last_ = timestamp;
    const double raw_derivative = (value - value_) / seconds;
    const double a_d = alpha(derivative_cutoff_, seconds);
    derivative_ += a_d * (raw_derivative - derivative_);
    const double cutoff = min_cutoff_ + beta_ * std::abs(derivative_);
    value_ += alpha(cutoff, seconds) * (value - value_);
    return value_;
}

double ema_weight_after(const OutputSettings& settings, double seconds) noexcept {
    if (settings.ema_frame_rate <= 0.0 || seconds <= 0.0) return settings.ema_weight;
    return std::pow(settings.ema_weight, std::max(1.0, seconds * settings.ema_frame_rate));
}

PositionSmoother::PositionSmoother(const OutputSettings& settings) noexcept
    : settings_(settings),
      one_euro_{OneEuroFilter(settings.one_euro_min_cutoff, settings.one_euro_beta,
                              settings.one_euro_d_cutoff),
                OneEuroFilter(settings.one_euro_min_cutoff, settings.one_euro_beta,
                              settings.one_euro_d_cutoff),
                OneEuroFilter(settings.one_euro_min_cutoff, settings.one_euro_beta,
                              settings.one_euro_d_cutoff)} {}

void PositionSmoother::reset(cv::Point3d position, Timestamp timestamp) noexcept {
    smoothed_ = position;
    last_ = timestamp;
    has_last_ = true;
    one_euro_[0].reset(position.x, timestamp);
    one_euro_[1].reset(position.y, timestamp);
    one_euro_[2].reset(position.z, timestamp);
}

cv::Point3d PositionSmoother::update(cv::Point3d position, Timestamp timestamp) noexcept {
    switch (settings_.smoothing) {
        case SmoothingKind::ema: {
            const double seconds = has_last_ ? static_cast<double>(timestamp - last_) * 1e-6 : 0.0;
            const double w = ema_weight_after(settings_, seconds);
            smoothed_ = smoothed_ * w + position * (1.0 - w);
            break;
        }
        case SmoothingKind::one_euro:
            smoothed_ = {one_euro_[0].update(position.x, timestamp),
                         one_euro_[1].update(position.y, timestamp),
                         one_euro_[2].update(position.z, timestamp)};
            break;
    }
    last_ = timestamp;
    has_last_ = true;
    return smoothed_;
}

}  // namespace raypoint::core
