// SPDX-License-Identifier: MIT
// The raster estimator's neck cut (EstimatorSettings::neck_radius): a region that ran out
// through a narrow gap into what lies beyond keeps its own side; fingers and a limb crossing
// the border stay whole. On drawn edge images.

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/estimator.hpp"
#include "shapes.hpp"

namespace raypoint::core {
namespace {

EstimatorSettings with_neck(int radius) {
    EstimatorSettings settings;
    settings.neck_radius = radius;
    return settings;
}

double distance(cv::Point2f a, cv::Point2d b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

// A ball of radius 16 at (50, 60), a channel 7 px wide (5 px between its edge bands) and 6 px
// long from its right side to a box 24 px square: one region, as where a gap in a ball's
// outline opens onto a shelf behind it.
cv::Mat ball_through_a_gap() {
    cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::circle(mask, {50, 60}, 16, 1, cv::FILLED);
    cv::rectangle(mask, cv::Rect(64, 57, 8, 7), 1, cv::FILLED);
    cv::rectangle(mask, cv::Rect(72, 48, 24, 24), 1, cv::FILLED);
    return mask;
}

TEST(NeckCut, WhatLiesBeyondANarrowGapGoes) {
    const test::Shape region = test::outline(ball_through_a_gap());
    cv::Mat ball_mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::circle(ball_mask, {50, 60}, 16, 1, cv::FILLED);
    const test::Shape ball = test::outline(ball_mask);

    const Estimate whole = make_estimator(with_neck(0))->estimate(region.edges, {50, 60});
    const Estimate cut = make_estimator(with_neck(3))->estimate(region.edges, {50, 60});
    // Without the cut the box is in: the centroid is pulled right of the ball's centre.
    EXPECT_GT(whole.area, 1.3 * ball.area);
    EXPECT_GT(distance(whole.centroid, ball.centroid), 5.0);
    // With it, the ball and the channel's mouth: within 10% of the ball and 1.5 px of its centre.
    EXPECT_LT(std::abs(cut.area - ball.area) / ball.area, 0.10);
    EXPECT_LT(distance(cut.centroid, ball.centroid), 1.5);
}

TEST(NeckCut, ANeckWiderThanTheRadiusStays) {
    // The same with the channel 11 px wide (9 px between the bands): over 2 x 3 + 1, no cut.
    cv::Mat mask = ball_through_a_gap();
    cv::rectangle(mask, cv::Rect(64, 55, 8, 11), 1, cv::FILLED);
    const test::Shape region = test::outline(mask);
    const Estimate whole = make_estimator(with_neck(0))->estimate(region.edges, {50, 60});
    const Estimate cut = make_estimator(with_neck(3))->estimate(region.edges, {50, 60});
    EXPECT_DOUBLE_EQ(cut.area, whole.area);
    EXPECT_FLOAT_EQ(cut.centroid.x, whole.centroid.x);
}

TEST(NeckCut, FingersStay) {
    // A palm 24 px square with four fingers 5 px wide and 14 px long (3 px between the bands):
    // thin all along, no core of their own, kept with the palm.
    cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::rectangle(mask, cv::Rect(68, 60, 24, 24), 1, cv::FILLED);
    for (int finger = 0; finger < 4; ++finger)
        cv::rectangle(mask, cv::Rect(68 + 6 * finger, 46, 5, 14), 1, cv::FILLED);
    const test::Shape hand = test::outline(mask);
    const Estimate whole = make_estimator(with_neck(0))->estimate(hand.edges, {80, 72});
    const Estimate cut = make_estimator(with_neck(3))->estimate(hand.edges, {80, 72});
    EXPECT_DOUBLE_EQ(cut.area, whole.area);
    EXPECT_LT(std::abs(cut.area - hand.area) / hand.area, 0.10);
}

TEST(NeckCut, ARegionCrossingTheBorderIsLeftToTheExtremity) {
    // A ball on a forearm through a 7 px wrist, the forearm over the bottom border, the inner
    // point on the forearm: the wrist is a neck, but the far end is the ball's (extremity).
    cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::circle(mask, {80, 35}, 16, 1, cv::FILLED);
    cv::rectangle(mask, cv::Rect(77, 48, 7, 12), 1, cv::FILLED);
    cv::rectangle(mask, cv::Rect(70, 58, 21, 62), 1, cv::FILLED);
    const test::Shape arm = test::outline(mask);
    const Estimate whole = make_estimator(with_neck(0))->estimate(arm.edges, {80, 95});
    const Estimate cut = make_estimator(with_neck(3))->estimate(arm.edges, {80, 95});
    EXPECT_TRUE(cut.crosses_border);
    EXPECT_DOUBLE_EQ(cut.area, whole.area);
    EXPECT_FLOAT_EQ(cut.end_centroid.y, whole.end_centroid.y);
}

}  // namespace
}  // namespace raypoint::core
