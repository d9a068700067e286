// SPDX-License-Identifier: MIT
// The Poisson-disk filter's plan and stage on their own (paper 4.1): where each tap reads for
// an input size and format, and the stage's current and previous images.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "raypoint/core/filter_plan.hpp"
#include "raypoint/core/filter_stage.hpp"

namespace raypoint::core {
namespace {

using test::bgr_view;
using test::identity_settings;
using test::to_yuyv;
using test::uniform;

// lround(tap.x * 5): the taps' column offsets at radius 5 (test_preprocess.cpp checks them
// against poisson_disk_taps()); the largest is 5.
constexpr std::array<int, poisson_disk_tap_count> dx5{0,  -5, 5,  -1, 1,  2, -2, -4,
                                                      -1, 2,  -3, 3,  -1, 0, -4, 2};

FrameView geometry(int width, int height, PixelFormat format) {
    static const std::vector<std::uint8_t> bytes(1);
    FrameView view;
    view.data = bytes.data();
    view.width = width;
    view.height = height;
    view.stride = width * (format == PixelFormat::bgr ? 3 : 2);
    view.format = format;
    return view;
}

TEST(FilterPlan, MatchesNothingUntilBuiltThenOnlyItsGeometry) {
    FilterPlan plan({160, 120}, 5.0);
    EXPECT_FALSE(plan.matches(geometry(640, 480, PixelFormat::bgr)));
    plan.build(640, 480, PixelFormat::bgr);
    EXPECT_TRUE(plan.matches(geometry(640, 480, PixelFormat::bgr)));
    EXPECT_FALSE(plan.matches(geometry(640, 480, PixelFormat::yuyv)));
    EXPECT_FALSE(plan.matches(geometry(640, 360, PixelFormat::bgr)));
    EXPECT_FALSE(plan.matches(geometry(1280, 480, PixelFormat::bgr)));
    EXPECT_EQ(plan.input_width(), 640);
    EXPECT_EQ(plan.input_height(), 480);
    EXPECT_EQ(plan.format(), PixelFormat::bgr);
    EXPECT_EQ(plan.working(), cv::Size(160, 120));
    plan.build(320, 240, PixelFormat::yuyv);
    EXPECT_TRUE(plan.matches(geometry(320, 240, PixelFormat::yuyv)));
    EXPECT_FALSE(plan.matches(geometry(640, 480, PixelFormat::bgr)));
}

TEST(FilterPlan, Bgr640TapsReadAroundEachWorkingPixelsCentre) {
    FilterPlan plan({160, 120}, 5.0);
    plan.build(640, 480, PixelFormat::bgr);
    // Working column x of 160 spans input columns [4x, 4x + 4); its centre 4x + 1.5 rounds
    // away from zero to 4x + 2. Likewise rows.
    for (int x = 0; x < 160; ++x) {
        ASSERT_EQ(plan.centre_columns()[x], 4 * x + 2) << x;
        ASSERT_EQ(plan.centre_bytes()[x], 3 * (4 * x + 2)) << x;
    }
    for (int t = 0; t < poisson_disk_tap_count; ++t) {
        const FilterTap& tap = plan.taps()[t];
        EXPECT_EQ(tap.dx, dx5[t]) << "tap " << t;
        EXPECT_EQ(tap.shift_bytes, 3 * dx5[t]) << "tap " << t;
        ASSERT_EQ(tap.columns.size(), 160U);
        ASSERT_EQ(tap.rows.size(), 120U);
        for (int x = 0; x < 160; ++x)
            ASSERT_EQ(tap.columns[x], std::clamp(4 * x + 2 + dx5[t], 0, 639)) << t << " " << x;
        for (int y = 0; y < 120; ++y) {
            ASSERT_GE(tap.rows[y], std::max(0, 4 * y + 2 - 5)) << t << " " << y;
            ASSERT_LE(tap.rows[y], std::min(479, 4 * y + 2 + 5)) << t << " " << y;
        }
    }
    // The centre tap reads the centre itself.
    for (int y = 0; y < 120; ++y)
        ASSERT_EQ(plan.taps()[0].rows[y], 4 * y + 2) << y;
    for (int y = 0; y < 120; ++y) {
        int last = 0;
        for (const FilterTap& tap : plan.taps())
            last = std::max(last, tap.rows[y]);
        ASSERT_EQ(plan.last_tap_row(y), last) << y;
    }
    // Interior: a column of reach 5 plus one to spare on each side, 4x + 2 - 6 >= 0 and
    // 4x + 2 + 6 < 640, so x in [1, 158); no tap there is clamped.
    EXPECT_EQ(plan.interior_begin(), 1);
    EXPECT_EQ(plan.interior_end(), 158);
    EXPECT_TRUE(plan.uniform_parity());
}

TEST(FilterPlan, RadiusScalesWithTheInputWidth) {
    const auto& offsets = poisson_disk_taps();
    for (const int width : {320, 640, 1280, 1920}) {
        FilterPlan plan({160, 120}, 5.0);
        plan.build(width, width * 3 / 4, PixelFormat::bgr);
        const double radius = 5.0 * width / 640.0;
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            EXPECT_EQ(plan.taps()[t].dx, std::lround(offsets[t].x * radius))
                << "width " << width << " tap " << t;
        }
    }
}

TEST(FilterPlan, YuyvEvenCentresReadEachTapsYAtAFixedPlaceOfItsPair) {
    FilterPlan plan({160, 120}, 5.0);
    plan.build(640, 480, PixelFormat::yuyv);
    ASSERT_TRUE(plan.uniform_parity());
    for (int x = 0; x < 160; ++x)  // centre 4x + 2 is even: its pair starts there, 2 bytes each
        ASSERT_EQ(plan.centre_bytes()[x], 2 * (4 * x + 2)) << x;
    std::uint32_t odd = 0;
    for (int t = 0; t < poisson_disk_tap_count; ++t) {
        const FilterTap& tap = plan.taps()[t];
        // Column c + dx: the second of its pair when dx is odd; the pair starts at
        // c + (dx & ~1) (-5 -> pair at c - 6, second pixel).
        EXPECT_EQ(tap.odd_luma, (dx5[t] & 1) != 0) << "tap " << t;
        EXPECT_EQ(tap.shift_bytes, (dx5[t] & ~1) * 2) << "tap " << t;
        if (tap.odd_luma) odd |= 1U << t;
    }
    EXPECT_EQ(plan.odd_taps(), odd);
    EXPECT_EQ(plan.taps()[1].shift_bytes, -12);  // dx -5
    EXPECT_TRUE(plan.taps()[1].odd_luma);
}

TEST(FilterPlan, YuyvOddCentresShiftByOneColumnMore) {
    // 320 wide: centre of working column x is round(2x + 0.5) = 2x + 1, odd; its pair starts
    // at 2x. Radius 2.5.
    FilterPlan plan({160, 120}, 5.0);
    plan.build(320, 240, PixelFormat::yuyv);
    ASSERT_TRUE(plan.uniform_parity());
    for (int x = 0; x < 160; ++x) {
        ASSERT_EQ(plan.centre_columns()[x], 2 * x + 1) << x;
        ASSERT_EQ(plan.centre_bytes()[x], 4 * x) << x;
    }
    for (const FilterTap& tap : plan.taps()) {
        EXPECT_EQ(tap.odd_luma, ((1 + tap.dx) & 1) != 0) << tap.dx;
        EXPECT_EQ(tap.shift_bytes, ((1 + tap.dx) & ~1) * 2) << tap.dx;
    }
    EXPECT_TRUE(plan.taps()[0].odd_luma);  // the centre tap: the odd column itself
}

TEST(FilterPlan, MixedParityLeavesYuyvToThePlainLoops) {
    // 480 wide: centres round(3x + 1) = 3x + 1 alternate in parity.
    FilterPlan plan({160, 120}, 5.0);
    plan.build(480, 360, PixelFormat::yuyv);
    EXPECT_EQ(plan.centre_columns()[0], 1);
    EXPECT_EQ(plan.centre_columns()[1], 4);
    EXPECT_FALSE(plan.uniform_parity());
}

TEST(FilterPlan, NoInteriorWhenTheTapsReachPastBothSides) {
    // Radius 400 at 160 wide is 100 input pixels: no centre has 101 columns on both sides.
    FilterPlan plan({160, 120}, 400.0);
    plan.build(160, 120, PixelFormat::bgr);
    EXPECT_EQ(plan.interior_begin(), 0);
    EXPECT_EQ(plan.interior_end(), 0);
    for (const FilterTap& tap : plan.taps()) {
        for (const int column : tap.columns) {
            ASSERT_GE(column, 0);
            ASSERT_LT(column, 160);
        }
    }
}

// The border groups hold exactly the columns the interior kernels leave, each once, and per
// tap a 4-byte load inside the row whose selected bytes are the clamped column's B, G, R (YUYV:
// its own Y, its pair's U and V), widened to 16-bit lanes with the spare lane zero.
void expect_border_reads_the_clamped_columns(const FilterPlan& plan, int input_width,
                                             PixelFormat format) {
    const bool bgr = format == PixelFormat::bgr;
    const int row_bytes = input_width * (bgr ? 3 : 2);
    const bool kernels = bgr || plan.uniform_parity();
    std::vector<int> expected;
    for (int x = 0; x < plan.working().width; ++x) {
        if (!kernels || x < plan.interior_begin() ||
            x >= std::max(plan.interior_end(), plan.interior_begin()))
            expected.push_back(x);
    }
    std::vector<int> seen;
    for (const FilterBorderGroup& group : plan.border_groups()) {
        ASSERT_GE(group.count, 1);
        ASSERT_LE(group.count, 4);
        for (int k = 0; k < group.count; ++k)
            seen.push_back(group.columns[k]);
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const FilterBorderGroup::Tap& tap = group.taps[t];
            for (int k = 0; k < 4; ++k) {
                const int column = plan.taps()[t].columns[group.columns[k]];
                ASSERT_GE(tap.loads[k], 0);
                ASSERT_LE(tap.loads[k] + 4, row_bytes);
                const std::array<int, 3> wanted =
                    bgr ? std::array<int, 3>{column * 3, column * 3 + 1, column * 3 + 2}
                        : std::array<int, 3>{column * 2, (column & ~1) * 2 + 1,
                                             (column & ~1) * 2 + 3};
                for (int value = 0; value < 3; ++value) {
                    const int index = tap.select[k * 8 + value * 2];
                    ASSERT_GE(index, k * 4) << t << " " << k;
                    ASSERT_LT(index, k * 4 + 4) << t << " " << k;
                    EXPECT_EQ(tap.loads[k] + index - k * 4, wanted[value]) << t << " " << k;
                    EXPECT_EQ(tap.select[k * 8 + value * 2 + 1], 0x80) << t << " " << k;
                }
                EXPECT_EQ(tap.select[k * 8 + 6], 0x80);
                EXPECT_EQ(tap.select[k * 8 + 7], 0x80);
            }
        }
    }
    EXPECT_EQ(seen, expected);
}

TEST(FilterPlan, BorderGroupsReadTheClampedColumnsInsideTheRow) {
    struct Case {
        int width;
        PixelFormat format;
        double radius;
    };
    for (const Case& c : {Case{640, PixelFormat::bgr, 5.0}, Case{640, PixelFormat::yuyv, 5.0},
                          Case{1280, PixelFormat::bgr, 5.0}, Case{320, PixelFormat::yuyv, 5.0},
                          Case{480, PixelFormat::yuyv, 5.0}, Case{642, PixelFormat::bgr, 5.0},
                          Case{640, PixelFormat::bgr, 40.0}, Case{160, PixelFormat::bgr, 400.0}}) {
        FilterPlan plan({160, 120}, c.radius);
        plan.build(c.width, c.width * 3 / 4, c.format);
        SCOPED_TRACE(std::to_string(c.width) + (c.format == PixelFormat::bgr ? " BGR" : " YUYV") +
                     " radius " + std::to_string(c.radius));
        expect_border_reads_the_clamped_columns(plan, c.width, c.format);
    }
    // 640x480 BGR: the interior is [1, 158), one group of three.
    FilterPlan plan({160, 120}, 5.0);
    plan.build(640, 480, PixelFormat::bgr);
    ASSERT_EQ(plan.border_groups().size(), 1U);
    EXPECT_EQ(plan.border_groups()[0].count, 3);
    EXPECT_EQ(plan.border_groups()[0].columns, (std::array<int, 4>{0, 158, 159, 159}));
}

TEST(FilterStage, CurrentBecomesPreviousAndPlanesSplitTheColour) {
    FilterStage stage(identity_settings());
    EXPECT_FALSE(stage.has_previous());
    cv::Mat first = uniform({160, 120}, cv::Vec3b(10, 20, 30));
    first(cv::Rect(40, 30, 20, 10)).setTo(cv::Scalar(200, 100, 50));
    const cv::Mat second = uniform({160, 120}, cv::Vec3b(70, 80, 90));
    ASSERT_TRUE(stage.apply(bgr_view(first)));
    EXPECT_FALSE(stage.has_previous());
    // Identity settings: the working image is the input.
    EXPECT_EQ(cv::norm(stage.color(), first, cv::NORM_INF), 0.0);
    std::array<cv::Mat, 3> channels;
    cv::split(first, channels.data());
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(
            cv::norm(stage.planes().rowRange(c * 120, (c + 1) * 120), channels[c], cv::NORM_INF),
            0.0)
            << "plane " << c;
    }
    cv::Mat grey;
    cv::cvtColor(first, grey, cv::COLOR_BGR2GRAY);
    EXPECT_EQ(cv::norm(stage.gray(), grey, cv::NORM_INF), 0.0);
    ASSERT_TRUE(stage.apply(bgr_view(second)));
    EXPECT_TRUE(stage.has_previous());
    EXPECT_EQ(cv::norm(stage.color(), second, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(stage.previous_color(), first, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(stage.previous_gray(), grey, cv::NORM_INF), 0.0);
}

TEST(FilterStage, ANewGeometryForgetsThePreviousFrameAndARejectedOneChangesNothing) {
    FilterStage stage(PreprocessSettings{});
    const cv::Mat bgr = uniform({640, 480}, cv::Vec3b(10, 20, 30));
    ASSERT_TRUE(stage.apply(bgr_view(bgr)));
    ASSERT_TRUE(stage.apply(bgr_view(bgr)));
    EXPECT_TRUE(stage.has_previous());
    const test::Yuyv yuyv = to_yuyv(uniform({320, 240}, cv::Vec3b(10, 20, 30)));
    ASSERT_TRUE(stage.apply(yuyv.view()));
    EXPECT_FALSE(stage.has_previous());
    EXPECT_TRUE(stage.plan().matches(yuyv.view()));
    const cv::Mat before = stage.color().clone();
    FrameView odd = yuyv.view();
    odd.width = 319;  // YUYV needs whole pairs
    EXPECT_FALSE(stage.apply(odd));
    FrameView small = bgr_view(bgr);
    small.width = 100;  // narrower than the working image
    EXPECT_FALSE(stage.apply(small));
    EXPECT_EQ(cv::norm(stage.color(), before, cv::NORM_INF), 0.0);
    EXPECT_TRUE(stage.plan().matches(yuyv.view()));
    ASSERT_TRUE(stage.apply(yuyv.view()));
    EXPECT_TRUE(stage.has_previous());
}

}  // namespace
}  // namespace raypoint::core
