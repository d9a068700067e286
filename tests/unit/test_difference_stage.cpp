// SPDX-License-Identifier: MIT
// The difference stage on its own (paper 4.1): two drawn working images with a brightness
// jump and a moving square, against sums computed pixel by pixel here.

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "raypoint/core/difference_stage.hpp"

namespace raypoint::core {
namespace {

PreprocessSettings difference_settings(EdgeSource movement_source) {
    PreprocessSettings settings;  // 160x120 working images, 10 minima
    settings.movement_source = movement_source;
    return settings;
}

const cv::Rect square_before(20, 20, 16, 16);
const cv::Rect square_after(60, 40, 16, 16);

// Before: a flat 60 with a 220 square. After: the light is up by 30 to 39 (ten distinct
// steps, (x + 3y) mod 10) and the square has moved. The background's differences are 30..39,
// so the compensation offset is 39 and the background drops out.
cv::Mat grey_before() {
    cv::Mat image(120, 160, CV_8U, cv::Scalar(60));
    image(square_before).setTo(cv::Scalar(220));
    return image;
}

cv::Mat grey_after() {
    cv::Mat image(120, 160, CV_8U);
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 160; ++x)
            image.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(90 + (x + 3 * y) % 10);
    }
    image(square_after).setTo(cv::Scalar(220));
    return image;
}

// The movement value by definition: sum over pixels of max(0, |a - b| - offset).
double compensated_sum(const cv::Mat& a, const cv::Mat& b, int offset) {
    double sum = 0.0;
    for (int y = 0; y < a.rows; ++y) {
        for (int x = 0; x < a.cols; ++x) {
            const int d = std::abs(a.at<std::uint8_t>(y, x) - b.at<std::uint8_t>(y, x));
            sum += std::max(0, d - offset);
        }
    }
    return sum;
}

cv::Mat as_colour(const cv::Mat& grey) {
    cv::Mat colour;
    cv::merge(std::vector<cv::Mat>{grey, grey, grey}, colour);
    return colour;
}

TEST(DifferenceStage, BrightnessJumpIsCompensatedAndTheMovingSquareRemains) {
    const cv::Mat before = grey_before();
    const cv::Mat after = grey_after();
    DifferenceStage stage(difference_settings(EdgeSource::luma));
    stage.compute(after, before, as_colour(after), as_colour(before));
    EXPECT_EQ(stage.brightness_offset_applied(), 39);
    const cv::Mat& difference = stage.difference();
    // Where the square arrived: |220 - 60| - 39 = 121. Where it left: 220 - (90 + k) - 39.
    for (int y = square_after.y; y < square_after.br().y; ++y) {
        for (int x = square_after.x; x < square_after.br().x; ++x)
            ASSERT_EQ(difference.at<std::uint8_t>(y, x), 121) << y << " " << x;
    }
    EXPECT_EQ(difference.at<std::uint8_t>(20, 20), 220 - 90 - 39);
    EXPECT_EQ(difference.at<std::uint8_t>(20, 21), 220 - 91 - 39);
    // The background (the jump alone) is gone.
    EXPECT_EQ(cv::countNonZero(difference), 2 * 16 * 16);
    const double expected = compensated_sum(after, before, 39);
    EXPECT_EQ(stage.movement(), expected);
    EXPECT_EQ(stage.movement(), cv::sum(difference)[0]);
    EXPECT_GT(expected, 256.0 * 121.0);  // the arrival alone
}

TEST(DifferenceStage, MaxChannelMovementSeesAColourChangeTheGreyMisses) {
    // Equal grey images, so the grey difference (the image) is empty. The blue channel
    // changes: 0..9 over the background ((x) mod 10, offset 9) and by 100 on a 10x10 square,
    // so the channel movement is 100 * (100 - 9).
    const cv::Mat grey(120, 160, CV_8U, cv::Scalar(100));
    const cv::Mat before(120, 160, CV_8UC3, cv::Scalar(100, 100, 100));
    cv::Mat after = before.clone();
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 160; ++x)
            after.at<cv::Vec3b>(y, x)[0] = static_cast<std::uint8_t>(100 + x % 10);
    }
    after(cv::Rect(30, 30, 10, 10)).setTo(cv::Scalar(200, 100, 100));
    DifferenceStage channels(difference_settings(EdgeSource::max_channel));
    channels.compute(grey, grey, after, before);
    EXPECT_EQ(channels.movement(), 100.0 * 91.0);
    EXPECT_EQ(cv::countNonZero(channels.difference()), 0);
    EXPECT_EQ(channels.brightness_offset_applied(), 0);  // the grey image's offset
    DifferenceStage luma(difference_settings(EdgeSource::luma));
    luma.compute(grey, grey, after, before);
    EXPECT_EQ(luma.movement(), 0.0);
}

TEST(DifferenceStage, ResetClearsTheImageTheMovementAndTheOffset) {
    DifferenceStage stage(difference_settings(EdgeSource::luma));
    stage.compute(grey_after(), grey_before(), as_colour(grey_after()), as_colour(grey_before()));
    ASSERT_GT(stage.movement(), 0.0);
    stage.reset();
    EXPECT_EQ(stage.movement(), 0.0);
    EXPECT_EQ(stage.brightness_offset_applied(), 0);
    EXPECT_EQ(cv::countNonZero(stage.difference()), 0);
}

}  // namespace
}  // namespace raypoint::core
