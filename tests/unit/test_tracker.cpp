// SPDX-License-Identifier: MIT
// The Tracker end to end on synthetic 640x480 frames: a black disk on white with mild sensor
// noise, 30 fps. The noise matters: without it the difference image has so few distinct
// values that the brightness compensation (paper 4.1) removes most of a clean disk's movement.

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "frames.hpp"
#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/stage_instructions.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::core {
namespace {

Timestamp at(int frame) {
    return std::llround(frame * 1e6 / 30.0);
}

// The disk's centre in working pixels: fraction * size - 0.5 (tracker.cpp's pixel centres).
cv::Point2d working(cv::Point2d fraction) {
    return {fraction.x * 160 - 0.5, fraction.y * 120 - 0.5};
}
cv::Point2d working(cv::Point input) {
    return {(input.x + 0.5) / 4 - 0.5, (input.y + 0.5) / 4 - 0.5};
}

Settings settings() {
    Settings s;
    // Pinned rather than defaulted: a 12 px/frame disk measures about 27,000 here. The paper's
    // 57,600 would need a disk twice as fast.
    s.tracking.search_threshold = 19200.0;
    return s;
}

// Still at (200, 240) until frame 70, then 12 px a frame to the right.
cv::Point path(int frame) {
    return {200 + 12 * std::max(0, frame - 70), 240};
}

TEST(Tracker, InitializesSearchesThenTracksTheMovingDisk) {
    Tracker tracker(settings());
    cv::Point2d bias;  // summed signed error once estimated: pixel-centre conventions show here
    int estimated = 0;
    for (int i = 0; i < 100; ++i) {
        SCOPED_TRACE(::testing::Message() << "frame " << i);
        const cv::Mat image = test::noisy_disk(i, path(i), 50);
        const FrameResult r = tracker.process(test::bgr_view(image, at(i)));
        EXPECT_EQ(r.frame, i);
        EXPECT_EQ(r.timestamp, at(i));
        if (i < 60) {  // 60 frames = 2.0 s of frame time
            ASSERT_EQ(r.state, TrackerState::initializing);
        } else if (i <= 70) {  // the disk is still: nothing to find
            ASSERT_EQ(r.state, TrackerState::searching);
            EXPECT_LT(r.movement, 19200.0);
        } else {
            ASSERT_EQ(r.state, TrackerState::tracking);
            ASSERT_TRUE(r.has_target);
            EXPECT_EQ(r.area.has_value(), i > 71);  // unknown on the frame that picks it
            const cv::Point2d error = working(r.centroid) - working(path(i));
            // Measured: 1.6 px on the picking frame (centre of the difference's mass, between
            // the old and new place), 0.05 px once estimated.
            EXPECT_LE(std::hypot(error.x, error.y), i == 71 ? 3.0 : 1.5) << r.centroid;
            if (i > 71) {
                bias += error;
                ++estimated;
            }
        }
    }
    // A half-pixel slip between working and fraction coordinates would be a 0.5 px bias.
    ASSERT_EQ(estimated, 28);
    EXPECT_LE(std::abs(bias.x / estimated), 0.25);
    EXPECT_LE(std::abs(bias.y / estimated), 0.25);
}

TEST(Tracker, DepthGrowsWithTheDisk) {
    // Once tracked, the disk bounces left and right and grows from radius 50 to 80.
    Tracker tracker(settings());
    std::vector<double> z;
    std::vector<double> area;
    for (int i = 0; i < 120; ++i) {
        const int radius = i < 80 ? 50 : std::min(80, 50 + (i - 80));
        const int swing = (i / 10) % 2 == 0 ? (i % 10) : 10 - (i % 10);
        const cv::Point centre = i <= 70 ? cv::Point(300, 240) : cv::Point(260 + 12 * swing, 240);
        const cv::Mat image = test::noisy_disk(i, centre, radius);
        const FrameResult r = tracker.process(test::bgr_view(image, at(i)));
        if (i < 75) continue;
        SCOPED_TRACE(::testing::Message() << "frame " << i);
        ASSERT_EQ(r.state, TrackerState::tracking);
        ASSERT_TRUE(r.has_position);
        ASSERT_TRUE(r.area.has_value());
        z.push_back(r.position.z);
        area.push_back(*r.area);
    }
    // Before growing (frames 75-79) z stays near 0, the reference depth.
    for (std::size_t k = 0; k < 5; ++k)
        EXPECT_NEAR(z[k], 0.0, 0.01);
    // The area follows pi r^2 / (640 * 480): 0.0256 at r = 50, 0.0654 at r = 80 (the refined
    // area runs a few percent short at this size).
    EXPECT_NEAR(area.front(), 0.0256, 0.0256 * 0.1);
    EXPECT_NEAR(area.back(), 0.0654, 0.0654 * 0.1);
    // z = sqrt(area) - sqrt(reference) rises by about 0.256 - 0.160 = 0.096, smoothed.
    EXPECT_GT(z.back(), 0.07);
    EXPECT_LT(z.back(), 0.11);
    for (std::size_t k = 10; k < z.size(); ++k)
        EXPECT_GE(z[k], z[k - 5]) << k;
}

TEST(Tracker, UnreadableFramesAreSkipped) {
    Tracker tracker(settings());
    int i = 0;
    for (; i < 80; ++i)
        tracker.process(test::bgr_view(test::noisy_disk(i, path(i), 50), at(i)));
    const cv::Mat good = test::noisy_disk(i, path(i), 50);
    const cv::Mat small(80, 100, CV_8UC3, cv::Scalar::all(128));
    FrameView null_data = test::bgr_view(good, at(i));
    null_data.data = nullptr;
    FrameView short_stride = test::bgr_view(good, at(i));
    short_stride.stride = 100;
    FrameView odd_yuyv = test::bgr_view(good, at(i));
    odd_yuyv.format = PixelFormat::yuyv;
    odd_yuyv.width = 639;
    for (const FrameView& bad : {null_data, test::bgr_view(small, at(i)), short_stride, odd_yuyv}) {
        const FrameResult r = tracker.process(bad);
        EXPECT_EQ(r.state, TrackerState::tracking);  // the machine's state, untouched
        EXPECT_FALSE(r.has_target);
        EXPECT_FALSE(r.lost);
        EXPECT_EQ(r.movement, 0.0);
    }
    const FrameResult next = tracker.process(test::bgr_view(good, at(i)));
    EXPECT_EQ(next.frame, 84);  // skipped frames are still counted
    EXPECT_EQ(next.state, TrackerState::tracking);
    ASSERT_TRUE(next.has_target);
    const cv::Point2d error = working(next.centroid) - working(path(i));
    EXPECT_LE(std::hypot(error.x, error.y), 1.5);
}

TEST(Tracker, YuyvAndBgrOfTheSameSceneAgree) {
    Tracker bgr(settings());
    Tracker yuyv(settings());
    int compared = 0;
    for (int i = 0; i < 90; ++i) {
        const cv::Mat image = test::noisy_disk(i, path(i), 50);
        const test::Yuyv packed = test::to_yuyv(image, 32);
        const FrameResult a = bgr.process(test::bgr_view(image, at(i)));
        const FrameResult b = yuyv.process(packed.view(at(i)));
        SCOPED_TRACE(::testing::Message() << "frame " << i);
        ASSERT_EQ(a.state, b.state);
        if (!a.has_target || !a.area) continue;
        ASSERT_TRUE(b.has_target);
        const cv::Point2d d = working(a.centroid) - working(b.centroid);
        EXPECT_LE(std::hypot(d.x, d.y), 1.0);
        ++compared;
    }
    EXPECT_GE(compared, 15);
}

// The daemon switches the sets between frames while INITIALIZING (InstructionTrial): a Tracker
// switched every frame through every combination the CPU runs gives exactly what one that never
// switched gives, state, positions and images, for BGR and YUYV input.
TEST(Tracker, SwitchingInstructionSetsBetweenFramesChangesNothing) {
    const int widest = static_cast<int>(best_instruction_set());
    std::vector<StageInstructions> combinations;
    for (int f = 0; f <= widest; ++f) {
        for (int e = 0; e <= widest; ++e)
            combinations.push_back(
                {static_cast<InstructionSet>(f), static_cast<InstructionSet>(e)});
    }
    for (const bool packed : {false, true}) {
        SCOPED_TRACE(packed ? "YUYV" : "BGR");
        Tracker fixed(settings(), StageInstructions::both(InstructionSet::scalar));
        Tracker switched(settings());
        int tracked = 0;
        for (int i = 0; i < 90; ++i) {
            SCOPED_TRACE(::testing::Message() << "frame " << i);
            switched.set_instructions(
                combinations[static_cast<std::size_t>(i) % combinations.size()]);
            EXPECT_EQ(switched.instructions(),
                      combinations[static_cast<std::size_t>(i) % combinations.size()]);
            const cv::Mat image = test::noisy_disk(i, path(i), 50);
            const test::Yuyv yuyv = test::to_yuyv(image, 32);
            const FrameView view = packed ? yuyv.view(at(i)) : test::bgr_view(image, at(i));
            const FrameResult a = fixed.process(view);
            const FrameResult b = switched.process(view);
            ASSERT_EQ(a.state, b.state);
            ASSERT_EQ(a.has_target, b.has_target);
            EXPECT_EQ(a.movement, b.movement);
            EXPECT_EQ(a.iterations, b.iterations);
            EXPECT_EQ(a.centroid, b.centroid);
            EXPECT_EQ(a.inner, b.inner);
            EXPECT_EQ(a.area, b.area);
            ASSERT_EQ(a.has_position, b.has_position);
            EXPECT_EQ(a.position, b.position);
            tracked += a.has_position ? 1 : 0;
            for (const auto& [x, y] :
                 {std::pair{&fixed.images().color, &switched.images().color},
                  std::pair{&fixed.images().edges, &switched.images().edges},
                  std::pair{&fixed.images().difference, &switched.images().difference}}) {
                ASSERT_EQ(cv::norm(*x, *y, cv::NORM_INF), 0.0);
            }
        }
        EXPECT_GE(tracked, 15);  // the comparison covered tracking, not only the start
    }
}

}  // namespace
}  // namespace raypoint::core
