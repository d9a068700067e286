// SPDX-License-Identifier: MIT
// The raster estimator's region where an outline is not whole: a limb crossing the image border
// (EstimatorSettings::extremity, extremity_contact) and an outline with a gap at the edge
// threshold (weak_edge_threshold, weak_wander), on drawn edge images.

#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/estimator.hpp"
#include "shapes.hpp"

namespace raypoint::core {
namespace {

double centroid_error(const Estimate& e, cv::Point2d truth) {
    return std::hypot(e.centroid.x - truth.x, e.centroid.y - truth.y);
}

double area_error(const Estimate& e, double truth) {
    return (e.area - truth) / truth;
}

// A ball held up on an arm that comes in over the bottom border: one region without an edge
// between them (the rays run down the arm), 160x120 with a 2 px outline.
cv::Mat arm_and_ball() {
    cv::Mat mask(120, 160, CV_8U, cv::Scalar(0));
    cv::rectangle(mask, cv::Rect(70, 50, 21, 70), cv::Scalar(255), cv::FILLED);
    cv::circle(mask, {80, 35}, 18, cv::Scalar(255), cv::FILLED);
    cv::Mat eroded;
    cv::erode(mask, eroded, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
    return mask - eroded;  // the outline, 2 px inside; none along the image border
}

TEST(RasterExtremity, ARegionOverTheBorderHasItsFarEnd) {
    const cv::Mat edges = arm_and_ball();
    EstimatorSettings settings;
    settings.extremity = 0.5;
    settings.extremity_contact = 16;
    const Estimate e = make_estimator(settings)->estimate(edges, {80, 70});
    ASSERT_TRUE(e.crosses_border);
    // The whole region's centroid is down the arm. The far end (beyond half the 102 px from the
    // crossing at y = 119 to the ball's top at 17: y < 68) is the ball and the arm's top 18 px:
    // its centroid and inner point are on the ball, above where the arm joins it (y = 50).
    EXPECT_GT(e.centroid.y, 55.0F);
    EXPECT_LT(e.end_centroid.y, 50.0F);
    EXPECT_LT(std::hypot(e.end_centroid.x - 80.0F, e.end_centroid.y - 35.0F), 10.0F);
    EXPECT_LT(std::hypot(e.end_inner.x - 80.0F, e.end_inner.y - 35.0F), 10.0F);
    EXPECT_EQ(edges.at<std::uint8_t>(cvRound(e.end_inner.y), cvRound(e.end_inner.x)), 0);
    EXPECT_GT(e.end_area, 0.3 * e.area);
    EXPECT_LT(e.end_area, 0.8 * e.area);

    settings.extremity_contact = 22;  // the arm is 21 px wide where it crosses
    EXPECT_FALSE(make_estimator(settings)->estimate(edges, {80, 70}).crosses_border);
    settings.extremity = 0.0;  // off: the paper's whole region
    settings.extremity_contact = 16;
    EXPECT_FALSE(make_estimator(settings)->estimate(edges, {80, 70}).crosses_border);
}

// The same outline drawn around `mask`: 2 px inside it, none along the image border.
cv::Mat outline_of(const cv::Mat& mask) {
    cv::Mat eroded;
    cv::erode(mask, eroded, cv::getStructuringElement(cv::MORPH_RECT, {5, 5}));
    return mask - eroded;
}

TEST(RasterExtremity, ANarrowForearmIsALimb) {
    // A forearm 7 px wide inside its outline where it crosses: the rendered sleeves' forearms
    // meet the border in runs under 8 px at 160x120.
    cv::Mat mask(120, 160, CV_8U, cv::Scalar(0));
    cv::rectangle(mask, cv::Rect(75, 50, 11, 70), cv::Scalar(255), cv::FILLED);
    cv::circle(mask, {80, 35}, 18, cv::Scalar(255), cv::FILLED);
    EstimatorSettings settings;
    settings.extremity = 0.5;
    settings.extremity_contact = 4;
    const Estimate e = make_estimator(settings)->estimate(outline_of(mask), {80, 35});
    ASSERT_TRUE(e.crosses_border);
    EXPECT_LT(std::hypot(e.end_centroid.x - 80.0F, e.end_centroid.y - 35.0F), 10.0F);
    settings.extremity_contact = 8;  // longer than the 7 px run
    EXPECT_FALSE(make_estimator(settings)->estimate(outline_of(mask), {80, 35}).crosses_border);
}

TEST(RasterExtremity, FingertipsPastTheBorderAreNoLimb) {
    // A palm whose four fingers run out over the top border: four runs of 4 px along it, 16
    // border pixels in all. No run holds half of them, so the region is the whole hand, not its
    // far end from the fingertips (the palm's heel).
    cv::Mat mask(120, 160, CV_8U, cv::Scalar(0));
    cv::circle(mask, {80, 50}, 22, cv::Scalar(255), cv::FILLED);
    for (const int x : {58, 70, 82, 94})
        cv::rectangle(mask, cv::Rect(x, 0, 8, 45), cv::Scalar(255), cv::FILLED);
    const cv::Mat edges = outline_of(mask);
    ASSERT_EQ(edges.at<std::uint8_t>(0, 61), 0);  // a fingertip's inside meets the border
    EstimatorSettings settings;
    settings.extremity = 0.5;
    settings.extremity_contact = 4;
    EXPECT_FALSE(make_estimator(settings)->estimate(edges, {80, 50}).crosses_border);
    // A run of 4 is a limb where it is all of the contact: one finger alone.
    cv::Mat finger(120, 160, CV_8U, cv::Scalar(0));
    cv::circle(finger, {80, 50}, 22, cv::Scalar(255), cv::FILLED);
    cv::rectangle(finger, cv::Rect(76, 0, 8, 45), cv::Scalar(255), cv::FILLED);
    EXPECT_TRUE(make_estimator(settings)->estimate(outline_of(finger), {80, 50}).crosses_border);
}

TEST(RasterExtremity, ARegionInsideThePictureIsWhole) {
    const test::Shape disk = test::disk();
    EstimatorSettings settings;
    settings.extremity = 0.5;
    settings.extremity_contact = 1;
    EXPECT_FALSE(make_estimator(settings)->estimate(disk.edges, {70, 55}).crosses_border);
}

// The disk's outline as a Sobel magnitude: 150 but for a 9 px stretch of its right side at 60,
// a gap at the default edge threshold (96) that the weaker edges (over 48) close. The rays run
// out through it and the region takes in the whole frame.
cv::Mat disk_magnitude_with_gap() {
    const test::Shape disk = test::disk();
    cv::Mat magnitude = disk.edges * 150;
    magnitude(cv::Rect(95, 56, 8, 9)).setTo(60, disk.edges(cv::Rect(95, 56, 8, 9)));
    return magnitude;
}

TEST(RasterWeakEdges, ARegionThatRanOutIsEstimatedAgainOnTheWeakerEdges) {
    const test::Shape disk = test::disk();
    const cv::Mat magnitude = disk_magnitude_with_gap();
    cv::Mat edges;
    cv::threshold(magnitude, edges, 96, 0, cv::THRESH_TOZERO);
    EstimatorSettings settings;
    settings.weak_edge_threshold = 0;    // the paper's: the region runs out through the gap
    const double largest = 0.6 * 19200;  // the frame's 60%
    EXPECT_GT(make_estimator(settings)->estimate(edges, {70, 55}).area, largest);

    settings.weak_edge_threshold = 48;
    auto estimator = make_estimator(settings);
    estimator->use_magnitude({&magnitude, 0.01 * 19200, largest});
    const Estimate e = estimator->estimate(edges, {70, 55});
    EXPECT_FALSE(e.leaked);
    EXPECT_LE(centroid_error(e, disk.centroid), 0.5);
    EXPECT_LE(std::abs(area_error(e, disk.area)), 0.05) << e.area;

    // A target's size bounds the second estimate: one smaller than the disk can be is not taken.
    estimator->use_magnitude({&magnitude, 2000.0, largest});
    EXPECT_GT(estimator->estimate(edges, {70, 55}).area, largest);
}

// The disk's outline at 150 with a line across its middle at 60: on the weaker edges it is two
// half disks.
cv::Mat disk_cut_across_magnitude() {
    cv::Mat magnitude = test::disk().edges * 150;
    cv::line(magnitude, {63, 60}, {97, 60}, cv::Scalar(60));
    return magnitude;
}

// One estimate from `inner` on the magnitude's edges over the default edge threshold (96), with
// the weaker edges at their default (40) and a target's size 1-60% of the frame.
Estimate estimate_on(const cv::Mat& magnitude, cv::Point2f inner, double weak_wander) {
    cv::Mat edges;
    cv::threshold(magnitude, edges, 96, 0, cv::THRESH_TOZERO);
    EstimatorSettings settings;
    settings.weak_wander = weak_wander;
    auto estimator = make_estimator(settings);
    estimator->use_magnitude({&magnitude, 0.01 * 19200, 0.6 * 19200});
    return estimator->estimate(edges, inner);
}

TEST(RasterWeakEdges, AWholeOutlineIsEstimatedOnce) {
    // Without a leak, or a region too large, the weaker edges are not looked at: a magnitude
    // that would cut the disk in two changes nothing.
    const Estimate e = estimate_on(disk_cut_across_magnitude(), {70, 55}, 16.0);
    EXPECT_FALSE(e.leaked);
    EXPECT_LE(std::abs(area_error(e, test::disk().area)), 0.05) << e.area;
}

// The disk with a wall above it: a closed region of the wall's outline (shelves all round) that
// the disk's outline touches along its top, where 9 px of it are at 60, a gap at the default
// edge threshold. Through the gap the region takes in the wall, 3 times the disk's size: no
// leak, no size too large, but its centroid is the wall's.
cv::Mat disk_under_wall_magnitude() {
    const test::Shape disk = test::disk();
    cv::Mat wall_mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::rectangle(wall_mask, cv::Rect(20, 2, 120, 38), 1, cv::FILLED);
    const test::Shape wall = test::outline(wall_mask);
    cv::Mat magnitude = (disk.edges | wall.edges) * 150;
    magnitude(cv::Rect(76, 37, 9, 5)).setTo(60, magnitude(cv::Rect(76, 37, 9, 5)) > 0);
    return magnitude;
}

TEST(RasterWeakEdges, ARegionWhoseInnerPointWanderedIsEstimatedAgain) {
    const test::Shape disk = test::disk();
    const cv::Mat magnitude = disk_under_wall_magnitude();
    // Never looked at again: the region is the disk and the wall.
    const Estimate merged = estimate_on(magnitude, {80, 60}, 0.0);
    EXPECT_FALSE(merged.leaked);
    EXPECT_GT(merged.area, 2.0 * disk.area);
    EXPECT_GT(cv::norm(merged.inner - cv::Point2f(80, 60)), 24.0F);

    const Estimate e = estimate_on(magnitude, {80, 60}, 16.0);
    EXPECT_LE(centroid_error(e, disk.centroid), 0.5);
    EXPECT_LE(std::abs(area_error(e, disk.area)), 0.05) << e.area;
}

TEST(RasterWeakEdges, AnInnerPointMovingWithItsTargetIsEstimatedOnce) {
    // The disk whole, its inner point 12 px from its centre (a hand that moved that far since
    // the last frame): the estimate moves it less than weak_wander, and the weaker edges, which
    // would cut the disk in two, are not looked at.
    const Estimate e = estimate_on(disk_cut_across_magnitude(), {72, 51}, 16.0);
    EXPECT_LE(std::abs(area_error(e, test::disk().area)), 0.05) << e.area;
}

TEST(RasterWeakEdges, AWeakerEstimateThatWandersTooIsNotTaken) {
    // The gap under the wall stays open on the weaker edges (30), which only cut the wall across
    // at y = 12: the second region is the disk and the wall's lower part, its inner point gone
    // 25 px into the wall. No better than the first: the first stands.
    cv::Mat magnitude = disk_under_wall_magnitude();
    magnitude(cv::Rect(76, 37, 9, 5)).setTo(30, magnitude(cv::Rect(76, 37, 9, 5)) > 0);
    cv::line(magnitude, {21, 12}, {138, 12}, cv::Scalar(60));
    const Estimate first = estimate_on(magnitude, {80, 60}, 0.0);
    const Estimate e = estimate_on(magnitude, {80, 60}, 16.0);
    EXPECT_GT(cv::norm(e.inner - cv::Point2f(80, 60)), 16.0F);
    EXPECT_DOUBLE_EQ(e.area, first.area);
}

}  // namespace
}  // namespace raypoint::core
