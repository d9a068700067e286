// SPDX-License-Identifier: MIT
#include "image_evidence.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core::detail {

// Paper 4.2: "the center of mass (i.e. the average position weighted by the pixel magnitude)
// of the absolute difference image". With SearchWeighting::strong only pixels at or above a
// share of the strongest difference weigh in: sensor noise spread over the whole frame
// otherwise pulls the centre toward the frame's middle, off a target entering at an edge.
std::optional<cv::Point2f> ImageEvidence::detect() noexcept {
    const cv::Mat& difference = images_.difference();
    int floor = 1;
    switch (settings_.search_weighting) {
        case SearchWeighting::all:
            break;
        case SearchWeighting::strong: {
            double strongest = 0.0;
            cv::minMaxLoc(difference, nullptr, &strongest);
            floor = std::max(1, static_cast<int>(strongest * settings_.strong_fraction));
            break;
        }
    }
    double sum = 0.0;
    double sum_x = 0.0;
    double sum_y = 0.0;
    for (int y = 0; y < difference.rows; ++y) {
        const auto* row = difference.ptr<std::uint8_t>(y);
        for (int x = 0; x < difference.cols; ++x) {
            if (row[x] < floor) continue;
            sum += row[x];
            sum_x += static_cast<double>(row[x]) * x;
            sum_y += static_cast<double>(row[x]) * y;
        }
    }
    if (sum <= 0.0) return std::nullopt;
    return cv::Point2f(static_cast<float>(sum_x / sum), static_cast<float>(sum_y / sum));
}

// The far end of a region crossing the border (EstimatorSettings::extremity) is the target when
// the scene's movement is there (a hand waving at the end of its sleeve); a still end is
// background the region leaked into (a door beside a ball), and the whole region stays. Once the
// end is the target it stays so while the region crosses the border: the hand pausing at the top
// of a push must not turn back into hand and sleeve, an area jump the click machine would take
// for a push.
Estimate ImageEvidence::estimate(cv::Point2f inner) noexcept {
    images_.ensure_edges();
    estimator_.use_color(&images_.color());
    const double pixels = static_cast<double>(images_.magnitude().total());
    estimator_.use_magnitude(
        {&images_.magnitude(), settings_.min_area * pixels, settings_.max_area * pixels});
    Estimate estimate = estimator_.estimate(images_.edges(), inner);
    if (!estimate.crosses_border) {
        on_end_ = false;
    } else if (on_end_ || end_is_moving(estimate)) {
        on_end_ = true;
        estimate.centroid = estimate.end_centroid;
        estimate.area = estimate.end_area;
        estimate.inner = estimate.end_inner;
    }
    return estimate;
}

Estimate ImageEvidence::look(cv::Point2f inner) noexcept {
    const bool on_end = on_end_;
    const Estimator::Memory memory = estimator_.memory();
    const Estimate estimate = ImageEvidence::estimate(inner);
    on_end_ = on_end;
    estimator_.restore(memory);
    return estimate;
}

// The end must hold a share of the scene's movement, and move at least as densely as the rest of
// the region: a hand waves at the end of a sleeve that only follows it, while a still door a ball
// touched on its way in is still near its far end even when the ball's movement is near enough
// to count toward the share.
bool ImageEvidence::end_is_moving(const Estimate& estimate) const noexcept {
    const float end_radius = motion_radius(estimate.end_area);
    const double end_movement = movement_near(estimate.end_centroid, end_radius);
    if (end_movement <= 0.0 || end_movement < settings_.extremity_motion * images_.movement())
        return false;
    const double rest_area = estimate.area - estimate.end_area;
    if (rest_area <= 0.0) return true;
    const cv::Point2f rest_centroid =
        (estimate.centroid * static_cast<float>(estimate.area) -
         estimate.end_centroid * static_cast<float>(estimate.end_area)) *
        static_cast<float>(1.0 / rest_area);
    const float rest_radius = motion_radius(rest_area);
    const double rest_movement = movement_near(rest_centroid, rest_radius);
    return end_movement / (end_radius * end_radius) >= rest_movement / (rest_radius * rest_radius);
}

double ImageEvidence::movement_near(cv::Point2f centre, float radius) const noexcept {
    const cv::Mat& difference = images_.difference();
    const int x0 = std::max(0, cvFloor(centre.x - radius));
    const int y0 = std::max(0, cvFloor(centre.y - radius));
    const int x1 = std::min(difference.cols - 1, cvCeil(centre.x + radius));
    const int y1 = std::min(difference.rows - 1, cvCeil(centre.y + radius));
    double sum = 0.0;
    for (int y = y0; y <= y1; ++y) {
        const auto* row = difference.ptr<std::uint8_t>(y);
        for (int x = x0; x <= x1; ++x)
            sum += row[x];
    }
    return sum;
}

// The patch is clipped to the image, so a point near the border still gets a colour.
cv::Vec3f ImageEvidence::patch_mean(const cv::Mat& color, cv::Point2f at) const noexcept {
    const int half = settings_.color_patch / 2;
    const int cx = std::clamp(cvRound(at.x), 0, color.cols - 1);
    const int cy = std::clamp(cvRound(at.y), 0, color.rows - 1);
    const int x0 = std::max(0, cx - half);
    const int x1 = std::min(color.cols - 1, cx + half);
    const int y0 = std::max(0, cy - half);
    const int y1 = std::min(color.rows - 1, cy + half);
    cv::Vec3f sum(0.0F, 0.0F, 0.0F);
    for (int y = y0; y <= y1; ++y) {
        const auto* row = color.ptr<cv::Vec3b>(y);
        for (int x = x0; x <= x1; ++x) {
            sum += cv::Vec3f(row[x][0], row[x][1], row[x][2]);
        }
    }
    const auto count = static_cast<float>((x1 - x0 + 1) * (y1 - y0 + 1));
    return sum / count;
}

}  // namespace raypoint::core::detail
