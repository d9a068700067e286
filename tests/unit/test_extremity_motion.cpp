// SPDX-License-Identifier: MIT
// Which part of a region that runs over the image border is the target (ImageEvidence::estimate
// with EstimatorSettings::extremity): the far end when it moves at least as densely as the rest
// (a hand waving at the end of its sleeve), the whole region when the movement is at the
// crossing (a ball coming in over the border whose region leaked into a still door).

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "frames.hpp"
#include "image_evidence.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/state_machine.hpp"

namespace raypoint::core {
namespace {

constexpr int scale = 4;  // 640x480 frames, 160x120 working pixels

// A grey room with one dark region: a bar from `bar` and a disk, of one colour, so no edge
// separates them.
cv::Mat scene(cv::Rect bar, cv::Point disk, int radius) {
    cv::Mat frame(480, 640, CV_8UC3, cv::Scalar(190, 190, 190));
    cv::rectangle(frame, bar, cv::Scalar(60, 60, 60), cv::FILLED);
    cv::circle(frame, disk, radius, cv::Scalar(60, 60, 60), cv::FILLED);
    return frame;
}

// The estimate of the second frame from `inner` (working pixels), the first frame being the
// previous one the movement is measured against.
Estimate estimate_after(const cv::Mat& previous, const cv::Mat& current, cv::Point2f inner,
                        double extremity) {
    Settings settings;
    settings.estimator.extremity = extremity;
    Preprocessor images(settings.preprocess);
    const std::unique_ptr<Estimator> estimator = make_estimator(settings.estimator);
    detail::ImageEvidence evidence(images, *estimator, settings.tracking,
                                   settings.preprocess.compensation_minima);
    EXPECT_TRUE(images.process(test::bgr_view(previous, 0), Preprocessor::Edges::computed));
    EXPECT_TRUE(images.process(test::bgr_view(current, 33333), Preprocessor::Edges::computed));
    return evidence.estimate(inner);
}

float distance(cv::Point2f a, cv::Point2f b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

TEST(ExtremityMotion, AWavingHandAtTheEndOfAStillSleeveIsTheTarget) {
    // The sleeve comes up from the bottom border to the hand, which moved 6 working pixels to
    // the right since the previous frame (the sleeve's top turned with it).
    const cv::Mat before = scene({280, 200, 80, 280}, {296, 180}, 56);
    const cv::Mat after = scene({280, 200, 80, 280}, {320, 180}, 56);
    const cv::Point2f hand(320.0F / scale, 180.0F / scale);
    const Estimate whole = estimate_after(before, after, {80, 100}, 0.0);
    const Estimate end = estimate_after(before, after, {80, 100}, 0.5);
    // The end (beyond half the reach from the bottom border) is the hand and the sleeve's top:
    // its centroid is inside the hand (radius 14), the whole region's below it.
    EXPECT_GT(distance(whole.centroid, hand), 18.0F) << whole.centroid;
    EXPECT_LT(distance(end.centroid, hand), 10.0F) << end.centroid;
    EXPECT_LT(end.area, 0.8 * whole.area);
}

TEST(ExtremityMotion, ABallComingInOverTheBorderKeepsTheStillDoorItLeakedInto) {
    // The ball comes in over the right border and touches a door above it: the region's far
    // end is the door's top, which does not move, though near enough to the ball for a tenth
    // of the frame's movement to be around it.
    const cv::Mat before = scene({520, 200, 80, 200}, {664, 380}, 80);
    const cv::Mat after = scene({520, 200, 80, 200}, {640, 380}, 80);
    const cv::Point2f inner(600.0F / scale, 380.0F / scale);
    const Estimate whole = estimate_after(before, after, inner, 0.0);
    const Estimate kept = estimate_after(before, after, inner, 0.5);
    EXPECT_LT(distance(kept.centroid, whole.centroid), 0.5F) << kept.centroid;
    EXPECT_NEAR(kept.area, whole.area, 1e-9);
}

TEST(ExtremityMotion, TheEndStaysTheTargetWhileTheHandPausesUntilTheTargetIsForgotten) {
    // The hand moves, then holds still (the top of a push): the estimate stays on the hand
    // instead of jumping back to hand and sleeve, an area change the click machine would read
    // as depth. A new target starts from the whole region again.
    const cv::Mat before = scene({280, 200, 80, 280}, {296, 180}, 56);
    const cv::Mat after = scene({280, 200, 80, 280}, {320, 180}, 56);
    const cv::Point2f hand(320.0F / scale, 180.0F / scale);
    Settings settings;
    Preprocessor images(settings.preprocess);
    const std::unique_ptr<Estimator> estimator = make_estimator(settings.estimator);
    detail::ImageEvidence evidence(images, *estimator, settings.tracking,
                                   settings.preprocess.compensation_minima);
    ASSERT_TRUE(images.process(test::bgr_view(before, 0), Preprocessor::Edges::computed));
    ASSERT_TRUE(images.process(test::bgr_view(after, 33333), Preprocessor::Edges::computed));
    EXPECT_LT(distance(evidence.estimate({80, 100}).centroid, hand), 10.0F);
    ASSERT_TRUE(images.process(test::bgr_view(after, 66667), Preprocessor::Edges::computed));
    ASSERT_EQ(images.movement(), 0.0);
    EXPECT_LT(distance(evidence.estimate({80, 100}).centroid, hand), 10.0F);
    evidence.forget_target();
    EXPECT_GT(distance(evidence.estimate({80, 100}).centroid, hand), 18.0F);
}

}  // namespace
}  // namespace raypoint::core
