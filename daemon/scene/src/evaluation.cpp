// SPDX-License-Identifier: MIT
#include "raypoint/scene/evaluation.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::scene {
namespace {

// numpy's median, as the scoring method takes it (docs/scoring.md): the mean of the two middle
// values of an even count.
std::optional<double> median(std::vector<double> values) {
    if (values.empty()) return std::nullopt;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (values.size() % 2 != 0) return *middle;
    return (*std::max_element(values.begin(), middle) + *middle) / 2.0;
}

std::optional<double> correlation(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() <= 10) return std::nullopt;
    const auto n = static_cast<double>(a.size());
    // Measured from the first sample, so a constant series (a fixed-size box, a fixed true
    // depth) has exactly zero variance instead of rounding noise that would pass for a value.
    double mean_a = 0.0, mean_b = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        mean_a += (a[i] - a[0]) / n;
        mean_b += (b[i] - b[0]) / n;
    }
    double cov = 0.0, var_a = 0.0, var_b = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double da = a[i] - a[0] - mean_a;
        const double db = b[i] - b[0] - mean_b;
        cov += da * db;
        var_a += da * da;
        var_b += db * db;
    }
    if (var_a <= 0.0 || var_b <= 0.0) return std::nullopt;
    return cov / std::sqrt(var_a * var_b);
}

// Whether any mask pixel lies within `pad` pixels (a square, as the scoring method's dilated
// window) of the point given as fractions of the frame.
bool near_mask(const cv::Mat& mask, cv::Point2d point, int pad) {
    const int px = std::clamp(static_cast<int>(point.x * mask.cols), 0, mask.cols - 1);
    const int py = std::clamp(static_cast<int>(point.y * mask.rows), 0, mask.rows - 1);
    const cv::Rect window = cv::Rect(px - pad, py - pad, 2 * pad + 1, 2 * pad + 1) &
                            cv::Rect(0, 0, mask.cols, mask.rows);
    return cv::countNonZero(mask(window)) > 0;
}

}  // namespace

void Evaluator::add(const Truth& truth, const cv::Mat& mask, const core::FrameResult& result) {
    if (truth.present && !entered_at_) entered_at_ = truth.t;
    if (truth.present && truth.moving && !first_motion_at_) first_motion_at_ = truth.t;
    if (first_motion_at_ && !first_detection_at_ && result.has_target) {
        first_detection_at_ = truth.t;
    }
    Sample sample;
    sample.scored =
        truth.present && truth.moving && entered_at_ && truth.t >= *entered_at_ + grace_seconds;
    if (sample.scored && result.has_target) {
        const int pad = static_cast<int>(std::lround(on_target_pad * mask.cols / 160.0));
        sample.on_target = near_mask(mask, result.centroid, pad);
    }
    if (sample.on_target) {
        sample.centroid_error = std::hypot((result.centroid.x - truth.cx) * 160.0,
                                           (result.centroid.y - truth.cy) * 120.0);
        if (result.area) sample.area_error = std::abs(*result.area - truth.area) / truth.area;
        if (result.has_position && truth.depth > 0.0) {
            sample.z = result.position.z;
            sample.inverse_depth = 1.0 / truth.depth;
        }
    }
    samples_.push_back(sample);
}

Evaluation Evaluator::result() const {
    Evaluation evaluation;
    std::vector<double> errors, areas, z, inverse_depth;
    for (const auto& sample : samples_) {
        if (!sample.scored) continue;
        ++evaluation.scored_frames;
        if (!sample.on_target) continue;
        ++evaluation.on_target;
        errors.push_back(sample.centroid_error);
        if (sample.area_error) areas.push_back(*sample.area_error);
        if (sample.z) {
            z.push_back(*sample.z);
            inverse_depth.push_back(sample.inverse_depth);
        }
    }
    evaluation.median_centroid_error = median(errors);
    evaluation.median_area_error = median(areas);
    evaluation.depth_correlation = correlation(z, inverse_depth);
    if (first_motion_at_ && first_detection_at_) {
        evaluation.detection_delay = *first_detection_at_ - *first_motion_at_;
    }
    return evaluation;
}

}  // namespace raypoint::scene
