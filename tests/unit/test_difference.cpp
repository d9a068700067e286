// SPDX-License-Identifier: MIT
// Brightness compensation and the movement value (paper 4.1), against hand-computed sums.

#include <vector>

#include <gtest/gtest.h>

#include "frames.hpp"
#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {
namespace {

using test::bgr_view;
using test::identity_settings;
using test::uniform;

// The paper's compensation alone (Compensation::frame), whose sums these tests work out by hand;
// the compensation by band of rows has its own tests (test_difference_stage.cpp).
PreprocessSettings paper_compensation(PreprocessSettings settings) {
    settings.compensation = Compensation::frame;
    return settings;
}

cv::Mat filled(cv::Size size, const std::vector<int>& values) {
    cv::Mat image(size, CV_8U);
    for (int i = 0; i < size.area(); ++i) {
        image.at<std::uint8_t>(i / size.width, i % size.width) =
            static_cast<std::uint8_t>(values[static_cast<std::size_t>(i) % values.size()]);
    }
    return image;
}

TEST(BrightnessOffset, LargestOfTheSmallestDistinctValues) {
    // {0..9}: the 10 distinct minima are 0..9, the largest 9.
    EXPECT_EQ(brightness_offset(filled({10, 10}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}), 10), 9);
    // {0..20}: still 9; the values above the tenth do not count.
    std::vector<int> to_twenty(21);
    for (int i = 0; i <= 20; ++i)
        to_twenty[static_cast<std::size_t>(i)] = i;
    EXPECT_EQ(brightness_offset(filled({21, 5}, to_twenty), 10), 9);
    // {0, 5, 7}: fewer distinct values than minima -> the largest present.
    EXPECT_EQ(brightness_offset(filled({3, 4}, {0, 5, 7}), 10), 7);
    // {3, 3, 4, 100}: distinct 3, 4, 100; repeats count once.
    const cv::Mat few = filled({4, 4}, {3, 3, 4, 100});
    EXPECT_EQ(brightness_offset(few, 1), 3);
    EXPECT_EQ(brightness_offset(few, 2), 4);
    EXPECT_EQ(brightness_offset(few, 3), 100);
    EXPECT_EQ(brightness_offset(few, 10), 100);
    // One pixel of 0 among many 50s still counts as the first minimum.
    cv::Mat mostly(20, 20, CV_8U, cv::Scalar(50));
    mostly.at<std::uint8_t>(3, 3) = 0;
    EXPECT_EQ(brightness_offset(mostly, 2), 50);
    EXPECT_EQ(brightness_offset(cv::Mat(5, 5, CV_8U, cv::Scalar(255)), 10), 255);
}

cv::Mat textured(cv::Size size, int add) {
    cv::Mat frame(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            const int v = 40 + (x * 7 + y * 13) % 150;
            frame.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(v + add),
                                                  static_cast<std::uint8_t>(v / 2 + 20 + add),
                                                  static_cast<std::uint8_t>(220 - v + add));
        }
    }
    return frame;
}

TEST(Difference, FirstFrameHasNoPrevious) {
    // Identity filter. Frame 1: grey 50 + d with d = (3x + y) mod 40; frame 2: 50 everywhere.
    // The difference is d. gcd(3, 40) = 1, so each row's 160 columns give every residue 0..39
    // four times. Offset: the tenth distinct value, 9. Compensated sum a row:
    // 4 * (1 + 2 + ... + 30) = 4 * 465 = 1860; 120 rows: 223200.
    cv::Mat first(120, 160, CV_8UC3);
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 160; ++x) {
            first.at<cv::Vec3b>(y, x) =
                cv::Vec3b::all(static_cast<std::uint8_t>(50 + (3 * x + y) % 40));
        }
    }
    Preprocessor pre(paper_compensation(identity_settings()));
    ASSERT_TRUE(pre.process(bgr_view(first)));
    EXPECT_FALSE(pre.has_previous());
    EXPECT_EQ(pre.movement(), 0.0);
    EXPECT_EQ(pre.brightness_offset_applied(), 0);
    EXPECT_EQ(cv::countNonZero(pre.difference()), 0);
    ASSERT_TRUE(pre.process(bgr_view(uniform({160, 120}, cv::Vec3b(50, 50, 50)))));
    EXPECT_TRUE(pre.has_previous());
    EXPECT_EQ(pre.brightness_offset_applied(), 9);
    EXPECT_EQ(pre.movement(), 223200.0);
}

TEST(Difference, UniformBrightnessJumpIsCompensatedAway) {
    // Every input channel +20: every tap sum +320, so every filtered channel is exactly +20 and
    // so is the grey (the grey coefficients sum to 1). The difference is 20 everywhere, the only
    // distinct value: offset 20, compensated difference 0, movement 0.
    Preprocessor pre(PreprocessSettings{});
    ASSERT_TRUE(pre.process(bgr_view(textured({640, 480}, 0))));
    ASSERT_TRUE(pre.process(bgr_view(textured({640, 480}, 20))));
    EXPECT_EQ(pre.brightness_offset_applied(), 20);
    EXPECT_EQ(pre.movement(), 0.0);
    EXPECT_EQ(cv::countNonZero(pre.difference()), 0);
}

TEST(Difference, MovingBlockOverSmallNoiseGivesTheExactCompensatedSum) {
    // Identity filter on 160x120 grey frames (equal channels: grey = the value exactly).
    // Frame 1: 50 everywhere. Frame 2: 50 + n with n = (x + 2y) mod 10, and 150 + n in the
    // 10x10 block x 40..49, y 30..39. Difference: n outside (all of 0..9 occur), 100 + n in the
    // block. The 10 smallest distinct values are 0..9 -> offset 9. Compensated: max(0, n - 9) =
    // 0 outside, 91 + n inside. In each block row x runs over 10 consecutive values, so n takes
    // each of 0..9 once: sum n = 45 a row, 450 in all. Movement = 100 * 91 + 450 = 9550.
    cv::Mat first = uniform({160, 120}, cv::Vec3b(50, 50, 50));
    cv::Mat second(120, 160, CV_8UC3);
    for (int y = 0; y < 120; ++y) {
        for (int x = 0; x < 160; ++x) {
            const int n = (x + 2 * y) % 10;
            const bool block = x >= 40 && x < 50 && y >= 30 && y < 40;
            second.at<cv::Vec3b>(y, x) =
                cv::Vec3b::all(static_cast<std::uint8_t>((block ? 150 : 50) + n));
        }
    }
    Preprocessor pre(paper_compensation(identity_settings()));
    ASSERT_TRUE(pre.process(bgr_view(first)));
    ASSERT_TRUE(pre.process(bgr_view(second)));
    EXPECT_EQ(pre.brightness_offset_applied(), 9);
    EXPECT_EQ(pre.movement(), 9550.0);
    EXPECT_EQ(pre.difference().at<std::uint8_t>(30, 40), 91 + 0);  // n = (40 + 60) mod 10 = 0
    EXPECT_EQ(pre.difference().at<std::uint8_t>(31, 45), 91 + 7);  // n = (45 + 62) mod 10 = 7
    EXPECT_EQ(pre.difference().at<std::uint8_t>(80, 100), 0);      // outside: n - 9 <= 0
    EXPECT_EQ(cv::countNonZero(pre.difference()), 100);

    // With 5 minima the offset is 4: outside, n = 5..9 leave 1..5; per 10 consecutive x that
    // is 15, over 160 columns 16 * 15 = 240 a row. Inside the block 96 + n.
    PreprocessSettings five = paper_compensation(identity_settings());
    five.compensation_minima = 5;
    Preprocessor pre5(five);
    ASSERT_TRUE(pre5.process(bgr_view(first)));
    ASSERT_TRUE(pre5.process(bgr_view(second)));
    EXPECT_EQ(pre5.brightness_offset_applied(), 4);
    // Rows: 120 * 240 = 28800, minus the block's outside value (sum 15 a block row, 150), plus
    // the block's 100 * 96 + 450 = 10050: 28800 - 150 + 10050 = 38700.
    EXPECT_EQ(pre5.movement(), 38700.0);
}

}  // namespace
}  // namespace raypoint::core
