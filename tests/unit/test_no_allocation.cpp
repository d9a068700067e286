// SPDX-License-Identifier: MIT
// Steady state does not allocate (estimator.hpp, tracker.hpp), counted by the replaced global
// operator new of tests/support/allocation_counter.cpp.

#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "frames.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/tracker.hpp"
#include "shapes.hpp"

namespace raypoint::core {
namespace {

using raypoint::test::allocations_during;

TEST(NoAllocation, TheCounterCounts) {
    // The replacement is in effect: a vector's growth is seen (else every test here is void).
    std::vector<int> grown;
    EXPECT_GE(allocations_during([&] { grown.resize(1000); }), 1);
    EXPECT_EQ(allocations_during([] {}), 0);
}

TEST(NoAllocation, EstimateAfterTheFirstCallOnTheSameSize) {
    const test::Shape disk = test::disk();
    const test::Hand hand = test::hand();
    for (const EstimatorKind kind : {EstimatorKind::ray, EstimatorKind::iterative_ray,
                                     EstimatorKind::iterative_ny_ray, EstimatorKind::raster}) {
        for (const AreaMode mode : {AreaMode::refined, AreaMode::blocks}) {
            EstimatorSettings settings;
            settings.kind = kind;
            settings.area_mode = mode;
            auto estimator = make_estimator(settings);
            estimator->estimate(disk.edges, {80.0F, 60.0F});  // warm-up
            const long count = allocations_during([&] {
                estimator->estimate(disk.edges, {70.0F, 55.0F});
                estimator->estimate(hand.shape.edges, hand.fingertips[2]);
                estimator->estimate(hand.shape.edges, hand.palm);
            });
            EXPECT_EQ(count, 0) << to_string(kind) << (mode == AreaMode::blocks ? " blocks" : "");
        }
    }
}

// With the movement's chain on (TrackingSettings::follow_movement) or off.
class TrackerNoAllocation : public ::testing::TestWithParam<double> {};

TEST_P(TrackerNoAllocation, ProcessInSteadyState) {
    // 40 frames of a disk moving on 640x480 BGR, built beforehand; 20 to warm up (the tracker
    // is tracking by then), 20 counted.
    constexpr int frames = 40;
    std::vector<cv::Mat> images;
    for (int i = 0; i < frames; ++i)
        images.push_back(test::noisy_disk(i, {100 + 12 * i, 240}, 50));
    Settings settings;
    settings.tracking.startup_seconds = 0.1;
    settings.tracking.search_threshold = 19200.0;  // see test_tracker.cpp
    settings.tracking.follow_movement = GetParam();
    Tracker tracker(settings);
    const auto view = [&](int i) {
        return test::bgr_view(images[static_cast<std::size_t>(i)], Timestamp{i} * 33'333);
    };
    for (int i = 0; i < 20; ++i)
        tracker.process(view(i));
    std::vector<FrameResult> results(frames);  // reserved: the loop below only assigns
    const long count = allocations_during([&] {
        for (int i = 20; i < frames; ++i)
            results[static_cast<std::size_t>(i)] = tracker.process(view(i));
    });
    for (int i = 20; i < frames; ++i) {
        ASSERT_EQ(results[static_cast<std::size_t>(i)].state, TrackerState::tracking)
            << "frame " << i;
    }
    EXPECT_EQ(count, 0);
}

INSTANTIATE_TEST_SUITE_P(FollowMovement, TrackerNoAllocation, ::testing::Values(0.0, 1.0));

}  // namespace
}  // namespace raypoint::core
