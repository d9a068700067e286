// SPDX-License-Identifier: MIT
#include "raypoint/core/smoothing.hpp"

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
    one_euro_[0].reset(position.x, timestamp);
    one_euro_[1].reset(position.y, timestamp);
    one_euro_[2].reset(position.z, timestamp);
}

cv::Point3d PositionSmoother::update(cv::Point3d position, Timestamp timestamp) noexcept {
    switch (settings_.smoothing) {
        case SmoothingKind::ema: {
            // Once a frame, as the paper does: the time constant is in frames, not seconds.
            const double w = settings_.ema_weight;
            smoothed_ = smoothed_ * w + position * (1.0 - w);
            break;
        }
        case SmoothingKind::one_euro:
            smoothed_ = {one_euro_[0].update(position.x, timestamp),
                         one_euro_[1].update(position.y, timestamp),
                         one_euro_[2].update(position.z, timestamp)};
            break;
    }
    return smoothed_;
}

}  // namespace raypoint::core
