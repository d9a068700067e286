// SPDX-License-Identifier: MIT
// The difference stage on its own (paper 4.1): two drawn working images with a brightness
// jump and a moving square, against sums computed pixel by pixel here; and the compensation by
// band of rows on mains flicker's bands.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "raypoint/core/difference_stage.hpp"

namespace raypoint::core {
namespace {

PreprocessSettings difference_settings(EdgeSource movement_source,
                                       Compensation compensation = Compensation::frame) {
    PreprocessSettings settings;  // 160x120 working images, 10 minima
    settings.movement_source = movement_source;
    settings.compensation = compensation;
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

// Mains flicker through a rolling shutter: each row's light changes by its own factor between
// two frames (here 0.8 to 1.2 along a sine over the rows), on a textured still scene, while a
// square moves. The paper's single offset leaves the bands; the compensation by band of rows
// leaves the square alone.
cv::Mat textured(double (*gain)(int row), cv::Rect square) {
    cv::Mat image(120, 160, CV_8U);
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 160; ++x) {
            const double texture = 90 + 60 * ((x / 8 + y / 6) % 3) + (x * 7 + y * 3) % 11;
            image.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(texture * gain(y));
        }
    }
    image(square).setTo(cv::Scalar(30));
    return image;
}

double unlit(int) {
    return 1.0;
}

double banded(int row) {
    return 1.0 + 0.2 * std::sin(2 * CV_PI * row / 48.0);
}

int band_pixels(const cv::Mat& difference, cv::Rect leave_out, int over) {
    int count = 0;
    for (int y = 0; y < difference.rows; ++y) {
        for (int x = 0; x < difference.cols; ++x) {
            if (!leave_out.contains({x, y}) && difference.at<std::uint8_t>(y, x) > over) ++count;
        }
    }
    return count;
}

TEST(DifferenceStage, RowCompensationRemovesFlickerBandsAndKeepsTheMovingSquare) {
    const cv::Rect before_square(20, 50, 16, 16);
    const cv::Rect after_square(28, 50, 16, 16);
    const cv::Mat before = textured(unlit, before_square);
    const cv::Mat after = textured(banded, after_square);
    const cv::Rect moved = before_square | after_square;
    DifferenceStage paper(difference_settings(EdgeSource::max_channel));
    paper.compute(after, before, as_colour(after), as_colour(before));
    DifferenceStage rows(difference_settings(EdgeSource::max_channel, Compensation::rows));
    rows.compute(after, before, as_colour(after), as_colour(before));
    // The paper's offset is the smallest differences' (the rows where the gain is near 1), so
    // most of the frame stays in the difference image; by band of rows, within a few levels.
    EXPECT_GT(band_pixels(paper.difference(), moved, 8), 160 * 120 / 3);
    EXPECT_LT(band_pixels(rows.difference(), moved, 8), 160 * 120 / 100);
    EXPECT_LT(rows.movement(), paper.movement() / 10);
    // The square's arrival (30 over a background of 90..250) stays strong.
    EXPECT_GT(rows.difference().at<std::uint8_t>(58, 40), 40);
    // The previous colour image in this frame's light: a still pixel's colour is kept.
    ASSERT_TRUE(rows.relit());
    EXPECT_FALSE(paper.relit());
    for (const cv::Point at : {cv::Point(100, 12), cv::Point(140, 36), cv::Point(80, 100)}) {
        const int now = after.at<std::uint8_t>(at);
        const cv::Vec3b relit = rows.previous_color_relit().at<cv::Vec3b>(at);
        EXPECT_NEAR(relit[0], now, 3) << at;
        EXPECT_NEAR(relit[2], now, 3) << at;
    }
    rows.reset();
    EXPECT_FALSE(rows.relit());
}

// Without a light change the compensation by rows is the paper's: the same image, bit for bit.
TEST(DifferenceStage, RowCompensationWithoutALightChangeIsThePapers) {
    const cv::Mat before = textured(unlit, cv::Rect(20, 50, 16, 16));
    const cv::Mat after = textured(unlit, cv::Rect(40, 60, 16, 16));
    DifferenceStage paper(difference_settings(EdgeSource::max_channel));
    paper.compute(after, before, as_colour(after), as_colour(before));
    DifferenceStage rows(difference_settings(EdgeSource::max_channel, Compensation::rows));
    rows.compute(after, before, as_colour(after), as_colour(before));
    EXPECT_EQ(cv::norm(paper.difference(), rows.difference(), cv::NORM_INF), 0.0);
    EXPECT_EQ(paper.movement(), rows.movement());
}

double lower_bands_brighter(int row) {
    return row >= 100 ? 1.3 : 1.0;
}

// A light change in the last five bands of rows alone is found (the 25 bands of still light
// before them are told apart without their median), and those bands are relit.
TEST(DifferenceStage, RowCompensationFindsALightChangeInTheLastBandsAlone) {
    const cv::Mat before = textured(unlit, cv::Rect(20, 50, 16, 16));
    const cv::Mat after = textured(lower_bands_brighter, cv::Rect(28, 50, 16, 16));
    DifferenceStage rows(difference_settings(EdgeSource::max_channel, Compensation::rows));
    rows.compute(after, before, as_colour(after), as_colour(before));
    ASSERT_TRUE(rows.relit());
    for (const cv::Point at : {cv::Point(100, 118), cv::Point(140, 119), cv::Point(100, 12)}) {
        const int now = after.at<std::uint8_t>(at);
        EXPECT_NEAR(rows.previous_color_relit().at<cv::Vec3b>(at)[1], now, 3) << at;
    }
}

double brighter(int) {
    return 1.25;
}

// light_change(): a gain jump lights every band alike (25% here, within a level's rounding);
// flicker's bands go brighter and darker by turns and share no change; the last five bands
// alone share none with the rest; still light is 0.
TEST(DifferenceStage, TheLightChangeIsWhatEveryBandShares) {
    const cv::Mat before = textured(unlit, cv::Rect(20, 50, 16, 16));
    DifferenceStage rows(difference_settings(EdgeSource::max_channel, Compensation::rows));
    const auto change = [&](double (*gain)(int)) {
        const cv::Mat after = textured(gain, cv::Rect(28, 50, 16, 16));
        rows.compute(after, before, as_colour(after), as_colour(before));
        return rows.light_change();
    };
    EXPECT_NEAR(change(brighter), 0.25, 0.02);
    EXPECT_EQ(change(banded), 0.0);
    EXPECT_EQ(change(lower_bands_brighter), 0.0);
    EXPECT_EQ(change(unlit), 0.0);
}

}  // namespace
}  // namespace raypoint::core
