// SPDX-License-Identifier: MIT
// The refined fill's diagonal steps (EstimatorSettings::diagonal_tolerance): a finger that is
// edge pixels but for a line of the hand's colour down its middle, cut from the palm by edges
// except for one diagonal step, belongs to the hand; the same line in the wall's colour (a gap
// in an outline) does not.

#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/estimator.hpp"

namespace raypoint::core {
namespace {

constexpr std::uint8_t strength = 200;     // every edge pixel's magnitude
const cv::Scalar hand_color(60, 80, 150);  // BGR
const cv::Scalar wall_color(190, 190, 190);

// 160x120: a palm (disk, 2 px outline) and a finger above it, the finger all edge pixels but
// for its middle column from y = 42 to 62. The column's last pixel (80, 62) touches the palm's
// open inside only diagonally, at (81, 63).
struct Hand {
    cv::Mat edges{120, 160, CV_8U, cv::Scalar(0)};
    cv::Mat color{120, 160, CV_8UC3, wall_color};
};

Hand hand(const cv::Scalar& finger_middle) {
    Hand h;
    cv::circle(h.edges, {80, 80}, 16, cv::Scalar(strength), 2);
    cv::rectangle(h.edges, cv::Rect(75, 40, 11, 25), cv::Scalar(strength), cv::FILLED);
    h.edges(cv::Rect(80, 42, 1, 21)).setTo(0);  // the finger's middle
    h.edges(cv::Rect(81, 63, 1, 8)).setTo(0);   // the palm's open inside, up to (81, 63)
    cv::circle(h.color, {80, 80}, 17, hand_color, cv::FILLED);
    cv::rectangle(h.color, cv::Rect(75, 40, 11, 25), hand_color, cv::FILLED);
    h.color(cv::Rect(80, 42, 1, 21)).setTo(finger_middle);
    return h;
}

Estimate estimate(const Hand& h, int tolerance, bool with_color = true) {
    EstimatorSettings settings;
    settings.diagonal_tolerance = tolerance;
    settings.extremity = 0.0;
    const std::unique_ptr<Estimator> estimator = make_estimator(settings);
    if (with_color) estimator->use_color(&h.color);
    return estimator->estimate(h.edges, {80, 80});
}

TEST(DiagonalFill, TheFingerOfTheHandsColourJoinsThePalm) {
    const Hand h = hand(hand_color);
    ASSERT_NE(h.edges.at<std::uint8_t>(63, 80), 0);  // the step is diagonal only
    ASSERT_NE(h.edges.at<std::uint8_t>(62, 81), 0);
    const Estimate palm = estimate(h, 0);
    const Estimate whole = estimate(h, 15);
    // The middle's 21 pixels and the band climbed from them, 3 px a side at half weight (a
    // flat band is all ridge): 21 + 21 * 6 / 2 = 84 more.
    EXPECT_NEAR(whole.area - palm.area, 84.0, 8.0);
    EXPECT_LT(whole.centroid.y, palm.centroid.y - 2.0F);
    EXPECT_NEAR(whole.centroid.x, palm.centroid.x, 0.5F);
}

TEST(DiagonalFill, AGapOfAnotherColourStaysShut) {
    const Hand h = hand(wall_color);
    EXPECT_DOUBLE_EQ(estimate(h, 15).area, estimate(h, 0).area);
}

TEST(DiagonalFill, WithoutTheColourImageOnlyFourNeighbours) {
    const Hand h = hand(hand_color);
    EXPECT_DOUBLE_EQ(estimate(h, 15, false).area, estimate(h, 0).area);
}

}  // namespace
}  // namespace raypoint::core
