// SPDX-License-Identifier: MIT
// What changed since the last quiet frame (QuietFrame, TrackingSettings::change_seconds), on
// the frames the Tracker works on (the preprocessed colour image).

#include <cstdint>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "quiet_frame.hpp"
#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {
namespace {

// A grey wall at 640x480 with a camera's noise (sigma 3 grey levels), and what the Tracker
// works on: the preprocessed 160x120 colour image.
cv::Mat wall(int seed) {
    cv::Mat frame(480, 640, CV_8UC3, cv::Scalar(150, 160, 170));
    cv::Mat noise(frame.size(), CV_16SC3);
    cv::RNG rng(static_cast<std::uint64_t>(seed));
    rng.fill(noise, cv::RNG::NORMAL, 0, 3);
    cv::Mat noisy;
    frame.convertTo(noisy, CV_16SC3);
    noisy += noise;
    noisy.convertTo(frame, CV_8UC3);
    return frame;
}

cv::Mat working(const cv::Mat& frame) {
    Preprocessor images(Settings{}.preprocess);
    EXPECT_TRUE(images.process(test::bgr_view(frame, 0), Preprocessor::Edges::deferred));
    return images.color().clone();
}

TEST(QuietFrame, TheChangeIsTheCentreOfWhatCameIn) {
    detail::QuietFrame quiet;
    const cv::Mat before = working(wall(1));
    cv::Mat frame = wall(2);
    cv::circle(frame, {400, 160}, 48, cv::Scalar(60, 90, 180), cv::FILLED);
    const cv::Mat now = working(frame);
    EXPECT_FALSE(quiet.change(now, 9600.0, 10));  // nothing kept yet
    quiet.keep(before);
    ASSERT_TRUE(quiet.kept());
    const auto found = quiet.change(now, 9600.0, 10);
    ASSERT_TRUE(found);
    EXPECT_NEAR(found->x, 100.0F - 0.5F, 0.5F);  // working pixel centres: (x + 0.5) * 4
    EXPECT_NEAR(found->y, 40.0F - 0.5F, 0.5F);
    // Over a small enough disk the change sums to less than the threshold.
    cv::Mat small = wall(3);
    cv::circle(small, {400, 160}, 8, cv::Scalar(60, 90, 180), cv::FILLED);
    EXPECT_FALSE(quiet.change(working(small), 9600.0, 10));
}

// An arm bent at the elbow: its centre of mass lies in the crook, on the wall. The pick must be on
// the arm itself.
TEST(QuietFrame, TheChangeIsOnWhatCameInWhereItsCentreOfMassIsNot) {
    detail::QuietFrame quiet;
    quiet.keep(working(wall(1)));
    cv::Mat frame = wall(2);
    const cv::Scalar skin(120, 150, 200);
    cv::rectangle(frame, cv::Rect(200, 120, 280, 70), skin, cv::FILLED);  // forearm
    cv::rectangle(frame, cv::Rect(410, 120, 70, 280), skin, cv::FILLED);  // upper arm
    const auto found = quiet.change(working(frame), 9600.0, 10);
    ASSERT_TRUE(found);
    const cv::Point2f full(found->x * 4.0F + 2.0F, found->y * 4.0F + 2.0F);  // 640x480 pixels
    const bool forearm = cv::Rect(200, 120, 280, 70).contains(full);
    const bool upper = cv::Rect(410, 120, 70, 280).contains(full);
    EXPECT_TRUE(forearm || upper) << full;
}

TEST(QuietFrame, TheSameSceneOrItAllBrighterIsNoChange) {
    detail::QuietFrame quiet;
    quiet.keep(working(wall(1)));
    // New noise: the paper's offset (the 10th smallest distinct difference) takes it out.
    EXPECT_FALSE(quiet.change(working(wall(2)), 9600.0, 10));
    // The whole picture 6 grey levels brighter (a camera's gain): the offset takes that out too.
    const cv::Mat brighter = wall(2) + cv::Scalar(6, 6, 6);
    EXPECT_FALSE(quiet.change(working(brighter), 9600.0, 10));
    // A frame of another size is no change, not a crash.
    EXPECT_FALSE(quiet.change(cv::Mat(60, 80, CV_8UC3, cv::Scalar(0, 0, 0)), 9600.0, 10));
}

}  // namespace
}  // namespace raypoint::core
