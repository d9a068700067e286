// SPDX-License-Identifier: MIT
// The state machine's rules that are not the paper's, as transcripts: letting go of a still
// target while the movement is elsewhere (abandon_seconds, abandon_grace, abandon_still_share)
// and holding back an estimate that grew too fast (max_growth). Working image 160x120
// (state_machine_testing.hpp).

#include <vector>

#include <gtest/gtest.h>

#include "state_machine_testing.hpp"

namespace raypoint::core {
namespace {

using test::play;
using test::Row;
using Ev = test::Event;
using St = TrackerState;
using namespace test::machine;

TEST(StateMachine, TargetIsDroppedWhenTheMovementStaysElsewhere) {
    // abandon_seconds 0.3 at 10 fps, share 0.1: from 0.3 s, 60,000 of movement with 5,000 of it
    // around the target. A frame at the share (6,000, not below) or with the whole under the
    // search threshold restarts the clock; the fourth frame away, at 0.3 s, drops the target
    // after estimating (the estimate says where the target is).
    TrackingSettings s = paper(2.0, true);
    s.abandon_seconds = 0.3;
    StateMachine machine(s, paper_size);
    // clang-format off
    play(machine, {
        {0.0,  0,     none, {},             {skin, {}}, St::searching},
        {0.1,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
        {0.2,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 6000},   // at the share
        {0.3,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},   // away from here
        {0.4,  57600, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 0},      // not over: reset
        {0.5,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},   // away from here
        {0.6,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {0.7,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {0.8,  60000, none, {est(P, 1000)}, {skin, {}}, St::searching, Ev::elsewhere, 5000},
        {0.9,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
    });
    // clang-format on
}

TEST(StateMachine, QuietFramesDoNotRestartTheTimeAwayOfATargetWithNoMovementAround) {
    // abandon_still_share 0.02: at 0.2 s none of the 60,000 is around the target (a window frame
    // beside a waving hand), so the frame at the search threshold at 0.3 s does not restart the
    // clock and the target is dropped at 0.5 s, 0.3 s after 0.2 s. The same with 5,000 around it
    // (8%: under abandon_share, over abandon_still_share) restarts at 0.3 s, as a hand at a turn.
    TrackingSettings s = paper(2.0, true);
    s.abandon_seconds = 0.3;
    s.abandon_still_share = 0.02;
    for (const double around : {0.0, 5000.0}) {
        SCOPED_TRACE(around);
        const bool dropped = around == 0.0;
        StateMachine machine(s, paper_size);
        // clang-format off
        play(machine, {
            {0.0, 0,     none, {},             {skin, {}}, St::searching},
            {0.1, 60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
            {0.2, 60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, around},
            {0.3, 57600, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, around},
            {0.4, 60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, around},
            {0.5, 60000, none, {est(P, 1000)}, {skin, {}},
             dropped ? St::searching : St::tracking, dropped ? Ev::elsewhere : Ev::none, around},
        });
        // clang-format on
    }
}

TEST(StateMachine, TargetThatMovedWithinTheGraceIsNotAbandoned) {
    // abandon_grace 0.5 s: the target had its share at 0.2 s, the movement is away from it from
    // 0.3 s; abandon_seconds (0.3) is over at 0.6 s, but the target is kept until 0.5 s after
    // its share, and dropped at 0.7 s. A target picked anew has no share yet: dropped once its
    // 0.3 s away are over.
    TrackingSettings s = paper(2.0, true);
    s.abandon_seconds = 0.3;
    s.abandon_grace = 0.5;
    StateMachine machine(s, paper_size);
    // clang-format off
    play(machine, {
        {0.0,  0,     none, {},             {skin, {}}, St::searching},
        {0.1,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
        {0.2,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 6000},   // its share
        {0.3,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},   // away from here
        {0.4,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {0.5,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {0.6,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},   // 0.3 s away
        {0.7,  60000, none, {est(P, 1000)}, {skin, {}}, St::searching, Ev::elsewhere, 5000},
        {0.8,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
        {0.9,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},   // away from here
        {1.0,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {1.1,  60000, none, {est(P, 1000)}, {skin, {}}, St::tracking,  Ev::none, 5000},
        {1.2,  60000, none, {est(P, 1000)}, {skin, {}}, St::searching, Ev::elsewhere, 5000},
    });
    // clang-format on
}

TEST(StateMachine, EstimateThatGrewTooFastIsHeldBack) {
    // max_growth 2 at 30 fps: a candidate over twice the last accepted area a frame after it is
    // held back (the last estimate stands, nothing is validated); the limit compounds with the
    // frames since that estimate (4 times after two), and growth_hold (0.05 s) ends a hold
    // whatever the limit. 12,000 square pixels is over max_area (11,520): dropped as before.
    TrackingSettings s = paper(2.0, true);
    s.min_area = 0.01;
    s.max_growth = 2.0;
    s.growth_hold = 0.05;
    StateMachine machine(s, paper_size);
    const cv::Point2f Q(70.0F, 50.0F);
    constexpr double f = 1.0 / 30.0;
    // clang-format off
    const test::Played played = play(machine, {
        {0.0,     0,     none, {},              {skin, {}}, St::searching},
        {1 * f,   60000, P,    {},              {skin, {}}, St::tracking,  Ev::acquired},
        {2 * f,   60000, none, {est(P, 1000)},  {skin, {}}, St::tracking},
        {3 * f,   60000, none, {est(Q, 11000)}, {skin, {}}, St::tracking},   // held: over 2,000
        {4 * f,   60000, none, {est(Q, 11000)}, {skin, {}}, St::tracking},   // held: over 4,000
        {5 * f,   60000, none, {est(Q, 11000)}, {skin, {}}, St::tracking},   // 0.067 s: taken
        {6 * f,   60000, none, {est(Q, 2500)},  {skin, {}}, St::tracking},   // smaller: taken
        {7 * f,   60000, none, {est(Q, 4750)},  {skin, {}}, St::tracking},   // under 5,000
        {8 * f,   60000, none, {est(Q, 9600)},  {skin, {}}, St::tracking},   // held: over 9,500
        {9 * f,   60000, none, {est(Q, 9600)},  {skin, {}}, St::tracking},   // under 19,000
        {10 * f,  60000, none, {est(Q, 12000)}, {skin, {}}, St::searching, Ev::too_large},
    });
    // clang-format on
    const std::vector<double> areas{1000, 1000, 1000, 11000, 2500, 4750, 4750, 9600};
    const std::vector<bool> held{false, true, true, false, false, false, true, false};
    for (std::size_t i = 0; i < areas.size(); ++i) {
        const core::StepResult& r = played.results[i + 2];
        EXPECT_TRUE(r.has_target) << "frame " << i + 2;
        EXPECT_EQ(r.estimate.area, areas[i]) << "frame " << i + 2;
        EXPECT_EQ(r.held, held[i]) << "frame " << i + 2;
    }
    // A held frame estimates once, from the last accepted inner point, and validates nothing.
    EXPECT_EQ(played.estimated_at[4], std::vector<cv::Point2f>{P});
    EXPECT_TRUE(played.painted_at[4].empty());
}

TEST(StateMachine, PickFollowsATargetThatMovedOnBeforeItsFirstEstimate) {
    // repick_difference 10 over the 5x5 colour patch (250 of movement around the pick), for
    // repick_seconds 0.3 after the first pick, at 10 fps: the pick at 0.1 s is uncovered
    // background at 0.2 s (300 around it), so the difference's centre of mass in that frame, Q,
    // is the pick, with no estimate. At 0.3 s the movement around Q is under the level (200):
    // Q is estimated, and after a first estimate no pick follows (0.4 s).
    TrackingSettings s = paper(2.0, true);
    s.repick_difference = 10;
    s.repick_seconds = 0.3;
    StateMachine machine(s, paper_size);
    const cv::Point2f Q(40.0F, 52.0F);
    const cv::Point2f R(30.0F, 54.0F);
    // clang-format off
    const test::Played played = play(machine, {
        {0.0,  0,     none, {},             {skin, {}}, St::searching},
        {0.1,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
        {0.2,  60000, Q,    {},             {skin, {}}, St::tracking,  Ev::acquired, 300},
        {0.3,  60000, R,    {est(Q, 1000)}, {skin, {}}, St::tracking,  Ev::none, 200},
        {0.4,  60000, R,    {est(Q, 1000)}, {skin, {}}, St::tracking,  Ev::none, 300},
    });
    // clang-format on
    EXPECT_EQ(played.results[2].estimate.centroid, Q);
    EXPECT_TRUE(played.estimated_at[2].empty());
    EXPECT_EQ(played.estimated_at[3], std::vector<cv::Point2f>{Q});
}

TEST(StateMachine, PickFollowsTheMovementForRepickSecondsAtMost) {
    // A pick whose patch stays in the movement follows it while 0.3 s have not passed since
    // the first pick (0.9-1.2 s, the bound included); at 1.3 s it is estimated where it is.
    TrackingSettings s = paper(2.0, true);
    s.repick_difference = 10;
    s.repick_seconds = 0.3;
    StateMachine machine(s, paper_size);
    const cv::Point2f Q(40.0F, 52.0F);
    // clang-format off
    play(machine, {
        {0.0,  0,     none, {},             {skin, {}}, St::searching},
        {0.9,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired},
        {1.0,  60000, Q,    {},             {skin, {}}, St::tracking,  Ev::acquired, 300},
        {1.1,  60000, P,    {},             {skin, {}}, St::tracking,  Ev::acquired, 300},
        {1.2,  60000, Q,    {},             {skin, {}}, St::tracking,  Ev::acquired, 300},
        {1.3,  60000, P,    {est(Q, 1000)}, {skin, {}}, St::tracking,  Ev::none, 300},
    });
    // clang-format on
}

TEST(StateMachine, TargetIsNeverAbandonedInThePaperPreset) {
    StateMachine machine(paper(2.0, false), paper_size);
    std::vector<Row> rows{{0.0, 0, none, {}, {skin, {}}, St::searching},
                          {0.1, 60000, P, {}, {skin, {}}, St::tracking, Ev::acquired}};
    for (int i = 2; i < 20; ++i) {
        rows.push_back(
            {i / 10.0, 60000, none, {est(P, 1000)}, {skin, {}}, St::tracking, Ev::none, 0.0});
    }
    play(machine, rows);
}

}  // namespace
}  // namespace raypoint::core
