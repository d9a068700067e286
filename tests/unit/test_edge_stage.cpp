// SPDX-License-Identifier: MIT
// The Sobel edge stage on its own (paper 4.1): drawn working images with known edges, no
// filter in front.

#include <gtest/gtest.h>

#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/edge_stage.hpp"

namespace raypoint::core {
namespace {

PreprocessSettings edge_settings(EdgeSource source, int threshold) {
    PreprocessSettings settings;  // 160x120 working images
    settings.edge_source = source;
    settings.edge_threshold = threshold;
    return settings;
}

const cv::Mat& unused_planes() {
    static const cv::Mat planes(360, 160, CV_8U, cv::Scalar(0));
    return planes;
}

TEST(EdgeStage, HorizontalLineGivesTwoEdgeRowsAndNoneOnIt) {
    // A 1-pixel line of height 20 on row 60 of a flat 40. Row 59: gy = (row 60) - (row 58) =
    // 20 + 2 * 20 + 20 = 80, gx = 0; row 61 the same negated; row 60: gy = 0. So magnitude 80
    // on rows 59 and 61, 0 elsewhere.
    cv::Mat grey(120, 160, CV_8U, cv::Scalar(40));
    grey.row(60).setTo(cv::Scalar(60));
    EdgeStage stage(edge_settings(EdgeSource::luma, 64));
    stage.compute(grey, unused_planes());
    for (int y = 0; y < 120; ++y) {
        const int want = (y == 59 || y == 61) ? 80 : 0;
        for (int x = 0; x < 160; ++x)
            ASSERT_EQ(stage.magnitude().at<std::uint8_t>(y, x), want) << y << " " << x;
    }
    EXPECT_EQ(cv::countNonZero(stage.edges()), 2 * 160);
    EXPECT_EQ(stage.edges().at<std::uint8_t>(59, 10), 80);  // edge pixels keep the magnitude
    // 80 is not over a threshold of 80.
    EdgeStage strict(edge_settings(EdgeSource::luma, 80));
    strict.compute(grey, unused_planes());
    EXPECT_EQ(cv::countNonZero(strict.magnitude()), 2 * 160);
    EXPECT_EQ(cv::countNonZero(strict.edges()), 0);
}

TEST(EdgeStage, BorderColumnsRepeatTheirNeighbour) {
    // Column 0 bright by 25: with the border replicated, columns 0 and 1 both see a step of
    // 25 between their left and right neighbours: 4 * 25 = 100.
    cv::Mat grey(120, 160, CV_8U, cv::Scalar(10));
    grey.col(0).setTo(cv::Scalar(35));
    EdgeStage stage(edge_settings(EdgeSource::luma, 96));
    stage.compute(grey, unused_planes());
    EXPECT_EQ(stage.magnitude().at<std::uint8_t>(0, 0), 100);
    EXPECT_EQ(stage.magnitude().at<std::uint8_t>(119, 1), 100);
    EXPECT_EQ(stage.magnitude().at<std::uint8_t>(50, 2), 0);
    EXPECT_EQ(cv::countNonZero(stage.edges()), 2 * 120);
}

TEST(EdgeStage, MaxChannelTakesTheStrongestPlaneNotTheirSum) {
    // Planes B, G, R one above the other: B steps by 10 at column 80 (magnitude 40), R by 30
    // (120), G flat. The strongest is R's 120; the norm over all planes would be 126. The grey
    // image is flat and not read.
    cv::Mat planes(360, 160, CV_8U, cv::Scalar(50));
    planes(cv::Rect(80, 0, 80, 120)).setTo(cv::Scalar(60));
    planes(cv::Rect(80, 240, 80, 120)).setTo(cv::Scalar(80));
    const cv::Mat flat(120, 160, CV_8U, cv::Scalar(50));
    EdgeStage stage(edge_settings(EdgeSource::max_channel, 96));
    stage.compute(flat, planes);
    for (int y = 0; y < 120; y += 17) {
        EXPECT_EQ(stage.magnitude().at<std::uint8_t>(y, 79), 120) << y;
        EXPECT_EQ(stage.magnitude().at<std::uint8_t>(y, 80), 120) << y;
        EXPECT_EQ(stage.magnitude().at<std::uint8_t>(y, 78), 0) << y;
    }
    EXPECT_EQ(cv::countNonZero(stage.edges()), 2 * 120);
    // Luma reads the flat grey image only.
    EdgeStage luma(edge_settings(EdgeSource::luma, 96));
    luma.compute(flat, planes);
    EXPECT_EQ(cv::countNonZero(luma.magnitude()), 0);
}

TEST(EdgeStage, RecomputingReplacesTheImages) {
    cv::Mat grey(120, 160, CV_8U, cv::Scalar(0));
    grey.colRange(80, 160).setTo(cv::Scalar(100));  // 4 * 100 saturates to 255
    EdgeStage stage(edge_settings(EdgeSource::luma, 128));
    stage.compute(grey, unused_planes());
    EXPECT_EQ(stage.magnitude().at<std::uint8_t>(5, 80), 255);
    EXPECT_EQ(cv::countNonZero(stage.edges()), 2 * 120);
    stage.compute(cv::Mat(120, 160, CV_8U, cv::Scalar(7)), unused_planes());
    EXPECT_EQ(cv::countNonZero(stage.magnitude()), 0);
    EXPECT_EQ(cv::countNonZero(stage.edges()), 0);
}

// Every instruction set gives the same bytes on full-range noise, whose gradients reach the
// largest squares and the 255 cap, at widths with and without a whole number of vector
// steps and below the widest kernel's minimum (17), for both sources and a low and a high
// threshold.
TEST(EdgeStage, EverySetGivesTheSameBytesOnNoise) {
    std::vector<InstructionSet> sets{InstructionSet::scalar};
    for (const InstructionSet set : {InstructionSet::sse2, InstructionSet::avx2}) {
        if (clamp_instruction_set(set, best_instruction_set()) == set) sets.push_back(set);
    }
    if (sets.size() == 1) GTEST_SKIP() << "this CPU runs no vector set";
    cv::RNG random(7);
    for (const int width : {160, 37, 18, 17}) {
        const int height = 24;
        cv::Mat grey(height, width, CV_8U);
        cv::Mat planes(3 * height, width, CV_8U);
        random.fill(grey, cv::RNG::UNIFORM, 0, 256);
        random.fill(planes, cv::RNG::UNIFORM, 0, 256);
        grey.row(5).setTo(cv::Scalar(0));  // a step of 255 both ways: the largest gradients
        grey.row(6).setTo(cv::Scalar(255));
        for (const EdgeSource source : {EdgeSource::luma, EdgeSource::max_channel}) {
            for (const int threshold : {8, 200}) {
                PreprocessSettings settings = edge_settings(source, threshold);
                settings.work_width = width;
                settings.work_height = height;
                EdgeStage reference(settings, InstructionSet::scalar);
                reference.compute(grey, planes);
                ASSERT_GT(cv::countNonZero(reference.edges()), 0);
                ASSERT_GT(cv::countNonZero(reference.magnitude() == 255), 0);
                for (const InstructionSet set : sets) {
                    EdgeStage stage(settings, set);
                    stage.compute(grey, planes);
                    EXPECT_EQ(cv::countNonZero(stage.magnitude() != reference.magnitude()), 0)
                        << to_string(set) << " width " << width;
                    EXPECT_EQ(cv::countNonZero(stage.edges() != reference.edges()), 0)
                        << to_string(set) << " width " << width;
                }
            }
        }
    }
}

}  // namespace
}  // namespace raypoint::core
