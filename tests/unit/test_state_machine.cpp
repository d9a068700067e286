// SPDX-License-Identifier: MIT
// The state machine (paper 4.2) as transcripts: one row a frame, features in, state out.
// Working image 160x120 = 19,200 pixels unless a test says otherwise, so the paper's
// thresholds apply unscaled: search above 57,600, idle below 4,800, area 2% = 384 to
// 60% = 11,520 square pixels.

#include <algorithm>
#include <optional>

#include <gtest/gtest.h>

#include "raypoint/core/settings.hpp"
#include "state_machine_testing.hpp"

namespace raypoint::core {
namespace {

using test::Event;
using test::Paint;
using test::play;
using test::Row;
using Ev = test::Event;
using St = TrackerState;
using namespace test::machine;

// INITIALIZING lasts startup_seconds of frame time, whatever the frame rate and wherever the
// clip's clock starts; movement during it is ignored.
int frames_initializing(double fps, double start_seconds) {
    TrackingSettings s = paper_settings().tracking;  // startup 2 s
    StateMachine machine(s, paper_size);
    const Row busy{0.0, 1e6, P, {}, {wall, {}}, St::searching};
    test::Script script;
    script.row = &busy;
    for (int frame = 0; frame < 1000; ++frame) {
        const auto t = static_cast<Timestamp>(std::llround((start_seconds + frame / fps) * 1e6));
        const StepResult r = machine.step(t, script);
        if (r.state != St::initializing) {
            EXPECT_EQ(r.state, St::searching);
            EXPECT_FALSE(r.acquired);  // the frame that ends the wait does not search
            EXPECT_EQ(machine.step(t + 1, script).state, St::tracking);  // the next one does
            return frame;
        }
    }
    return -1;
}

TEST(StateMachine, InitializingLastsStartupSecondsOfFrameTime) {
    EXPECT_EQ(frames_initializing(10.0, 0.0), 20);      // 20 / 10 fps = 2.0 s
    EXPECT_EQ(frames_initializing(60.0, 0.0), 120);     // 120 / 60 fps = 2.0 s
    EXPECT_EQ(frames_initializing(60.0, 5000.0), 120);  // a clock that starts at 5000 s
    EXPECT_EQ(frames_initializing(7.0, 0.0), 14);       // 13 / 7 = 1.86 s, 14 / 7 = 2.0 s
}

TEST(StateMachine, SearchStartsOverTheThresholdAtTheDetectedPoint) {
    StateMachine machine(paper(), paper_size);
    // clang-format off
    const auto played = play(machine, {
        //  t     movement  detect  estimate()       paint         -> state      event
        {0.0,    0,        none,   {},              {wall, {}},   St::searching},
        {0.1,    57600,    P,      {},              {wall, {}},   St::searching},  // not over it
        {0.2,    57601,    none,   {},              {wall, {}},   St::searching},  // no mass
        {0.3,    57601,    P,      {},              {skin, {}},   St::tracking,  Ev::acquired},
        {0.4,    9000,     none,   {est(P, 1000)},  {skin, {}},   St::tracking},
    });
    // clang-format on
    const StepResult& picked = played.results[3];
    EXPECT_EQ(picked.estimate.centroid, P);
    EXPECT_EQ(picked.estimate.inner, P);
    EXPECT_TRUE(played.estimated_at[3].empty());  // estimation starts with the next frame
    EXPECT_EQ(played.estimated_at[4], std::vector<cv::Point2f>{P});
    EXPECT_EQ(played.results[4].estimate.area, 1000.0);
    EXPECT_EQ(played.results[4].estimate.centroid, cv::Point2f(62.0F, 51.0F));
}

TEST(StateMachine, SearchThresholdScalesWithTheWorkingSize) {
    // 320x240 has 4x the pixels: the threshold is 4 * 57,600 = 230,400.
    StateMachine machine(paper(), cv::Size(320, 240));
    // clang-format off
    play(machine, {
        {0.0,    0,        none,   {},   {wall, {}},   St::searching},
        {0.1,    57601,    P,      {},   {wall, {}},   St::searching},
        {0.2,    230400,   P,      {},   {wall, {}},   St::searching},
        {0.3,    230401,   P,      {},   {skin, {}},   St::tracking,  Ev::acquired},
    });
    // clang-format on
}

TEST(StateMachine, TrackingFailsOutsideTheAreaRange) {
    StateMachine machine(paper(), paper_size);
    // clang-format off
    play(machine, {
        {0.0,    0,        none,   {},                {skin, {}},   St::searching},
        {0.1,    60000,    P,      {},                {skin, {}},   St::tracking,  Ev::acquired},
        {0.2,    9000,     none,   {est(P, 384)},     {skin, {}},   St::tracking},   // 2.000%
        {0.3,    9000,     none,   {est(P, 11520)},   {skin, {}},   St::tracking},   // 60.000%
        {0.4,    9000,     none,   {est(P, 383)},     {skin, {}},   St::searching, Ev::too_small},
        {0.5,    60000,    P,      {},                {skin, {}},   St::tracking,  Ev::acquired},
        {0.6,    9000,     none,   {est(P, 11521)},   {skin, {}},   St::searching, Ev::too_large},
    });
    // clang-format on
}

TEST(StateMachine, StillTargetIsDroppedAfterIdleSeconds) {
    // idle_seconds 0.5 at 10 fps. Movement below 4,800 from 0.3 s: dropped at 0.8 s, before
    // estimating. A frame at 4,800 (not below) restarts the clock.
    StateMachine machine(paper(0.5, false), paper_size);
    // clang-format off
    const auto played = play(machine, {
        {0.0,    0,        none,   {},               {skin, {}},   St::searching},
        {0.1,    60000,    P,      {},               {skin, {}},   St::tracking,  Ev::acquired},
        {0.2,    4800,     none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // not below
        {0.3,    4799,     none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // still from here
        {0.4,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {0.5,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {0.6,    4800,     none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // moved: reset
        {0.7,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // still from here
        {0.8,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {0.9,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {1.0,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {1.1,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // 0.4 s still
        {1.2,    0,        none,   {},               {skin, {}},   St::searching, Ev::still},
    });
    // clang-format on
    EXPECT_TRUE(played.estimated_at[12].empty());
}

TEST(StateMachine, KeptStillTargetStaysWhileItsColourMatches) {
    StateMachine machine(paper(0.5, true), paper_size);
    // clang-format off
    play(machine, {
        {0.0,    0,        none,   {},               {skin, {}},   St::searching},
        {0.1,    60000,    P,      {},               {skin, {}},   St::tracking,  Ev::acquired},
        {0.2,    9000,     none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {0.3,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // still from here
        {0.8,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},   // 0.5 s: kept
        {1.5,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
        {9.0,    0,        none,   {est(P, 1000)},   {skin, {}},   St::tracking},
    });
    // clang-format on
}

TEST(StateMachine, KeptStillTargetIsDroppedWhenItsColourChanged) {
    // The colour at the inner point creeps by 30 a frame (each frame validates against the
    // previous one) but the reference is the colour when the target last moved (0.2 s): once
    // still for 0.5 s, 150 away from it is too far. Before that the drift does not matter.
    StateMachine machine(paper(0.5, true), paper_size);
    // clang-format off
    play(machine, {
        {0.0,    0,     none,   {},               {skin, {}},                   St::searching},
        {0.1,    60000, P,      {},               {skin, {}},                   St::tracking, Ev::acquired},
        {0.2,    9000,  none,   {est(P, 1000)},   {skin, {}},                   St::tracking},
        {0.3,    0,     none,   {est(P, 1000)},   {plus(skin, 10, 10, 10), {}}, St::tracking},
        {0.4,    0,     none,   {est(P, 1000)},   {plus(skin, 20, 20, 20), {}}, St::tracking},
        {0.5,    0,     none,   {est(P, 1000)},   {plus(skin, 30, 30, 30), {}}, St::tracking},
        {0.6,    0,     none,   {est(P, 1000)},   {plus(skin, 40, 40, 40), {}}, St::tracking},
        {0.7,    0,     none,   {est(P, 1000)},   {plus(skin, 50, 50, 50), {}}, St::tracking},
        {0.8,    0,     none,   {est(P, 1000)},   {plus(skin, 60, 60, 60), {}}, St::searching, Ev::left},
    });
    // clang-format on
}

TEST(StateMachine, ValidationToleranceIsNinetyInclusive) {
    // Previous inner point's colour against the new one's: 30 + 30 + 30 = 90 passes;
    // 31 + 30 + 30 = 91 goes to RECOVERING, where no recovery point (all wall) matches.
    StateMachine machine(paper(), paper_size);
    // clang-format off
    const auto played = play(machine, {
        {0.0,  0,     none, {},             {wall, {}},                           St::searching},
        {0.1,  60000, P,    {},             {wall, {{P, skin}}},                  St::tracking, Ev::acquired},
        {0.2,  9000,  none, {est(P, 1000)}, {wall, {{P, plus(skin, 30, 30, 30)}}}, St::tracking},
        {0.3,  9000,  none, {est(P, 1000)}, {wall, {{P, plus(skin, 61, 60, 60)}}}, St::searching, Ev::no_point},
    });
    // clang-format on
    // RECOVERING looked at the 16 recovery points around the failed inner point P.
    EXPECT_EQ(played.results[3].recovery_from, std::optional<cv::Point2f>(P));
    EXPECT_FALSE(played.results[2].recovery_from.has_value());
    const auto& asked = played.painted_at[3];
    ASSERT_EQ(asked.size(), 17U);  // P itself, then the recovery points
    int found = 0;
    for (const int d : {10, 20}) {
        for (const cv::Point2f step :
             {cv::Point2f(1, 0), cv::Point2f(1, 1), cv::Point2f(0, 1), cv::Point2f(-1, 1),
              cv::Point2f(-1, 0), cv::Point2f(-1, -1), cv::Point2f(0, -1), cv::Point2f(1, -1)}) {
            found += static_cast<int>(
                std::count(asked.begin(), asked.end(), P + step * static_cast<float>(d)));
        }
    }
    EXPECT_EQ(found, 16);
}

// The 16 recovery points around Q = (80, 50): 10 and 20 px in the 8 directions.
const cv::Point2f Q(80.0F, 50.0F);

TEST(StateMachine, RecoveryPicksTheBestMatchingPointAndReestimatesThere) {
    // The estimate moves the inner point off the target (Q: wall). Among the recovery points
    // (70,50) is 20 away from skin, (60,50) 0 and (100,70) 50: (60,50), 20 px left, wins.
    const cv::Point2f best(60.0F, 50.0F);
    const cv::Point2f settled(61.0F, 51.0F);
    StateMachine machine(paper(), paper_size);
    const Paint scene{wall,
                      {{P, skin},
                       {{70.0F, 50.0F}, plus(skin, 20, 0, 0)},
                       {{100.0F, 70.0F}, plus(skin, 0, 50, 0)},
                       {settled, plus(skin, 5, 5, 5)}}};
    // clang-format off
    const auto played = play(machine, {
        {0.0,  0,     none, {},                               {wall, {{P, skin}}}, St::searching},
        {0.1,  60000, P,    {},                               {wall, {{P, skin}}}, St::tracking, Ev::acquired},
        {0.2,  9000,  none, {est(Q, 1000), est(settled, 1200)}, scene,             St::tracking, Ev::recovered},
    });
    // clang-format on
    EXPECT_EQ(played.estimated_at[2], (std::vector<cv::Point2f>{P, best}));
    const StepResult& r = played.results[2];
    EXPECT_EQ(r.estimate.inner, settled);
    EXPECT_EQ(r.estimate.area, 1200.0);
    EXPECT_EQ(r.iterations, 6);  // both estimates' iterations
    // Recovery points are around the failed inner point Q, near ones first.
    const auto& asked = played.painted_at[2];
    ASSERT_GE(asked.size(), 1U + 16U + 1U);  // Q, 16 recovery points, the re-estimate
    EXPECT_EQ(asked[1], cv::Point2f(90.0F, 50.0F));
    EXPECT_EQ(asked[9], cv::Point2f(100.0F, 50.0F));
    EXPECT_EQ(asked[17], settled);
    // The frame says where it searched (for drawing); frames without RECOVERING do not.
    ASSERT_TRUE(r.recovery_from.has_value());
    EXPECT_EQ(*r.recovery_from, Q);
    EXPECT_FALSE(played.results[1].recovery_from.has_value());
}

TEST(StateMachine, RecoveryFailsWhenTheReestimateDoesNotMatch) {
    const Paint scene{wall, {{P, skin}, {{70.0F, 50.0F}, skin}}};
    StateMachine machine(paper(), paper_size);
    // clang-format off
    play(machine, {
        {0.0,  0,     none, {},                                   {wall, {{P, skin}}}, St::searching},
        {0.1,  60000, P,    {},                                   {wall, {{P, skin}}}, St::tracking, Ev::acquired},
        {0.2,  9000,  none, {est(Q, 1000), est({90, 90}, 1000)},  scene,               St::searching, Ev::failed},
        {0.3,  60000, P,    {},                                   {wall, {{P, skin}}}, St::tracking, Ev::acquired},
        {0.4,  9000,  none, {est(Q, 1000), est({70, 50}, 100)},   scene,               St::searching, Ev::too_small},
    });
    // clang-format on
}

TEST(StateMachine, ATooSmallEstimateTriesTheRecoveryPointsWithRecoverSmall) {
    // A tracked target's estimate comes out at 100 px (under 384) with its inner point on the
    // wall: the recovery point (60,50) 20 px left matches and its estimate is taken. A target's
    // first estimate is not recovered so, and the paper loses it at once.
    TrackingSettings s = paper();
    s.recover_small = true;
    StateMachine machine(s, paper_size);
    const Paint scene{wall, {{P, skin}, {{60.0F, 50.0F}, skin}}};
    // clang-format off
    const auto played = play(machine, {
        {0.0,  0,     none, {},                                  {wall, {{P, skin}}}, St::searching},
        {0.1,  60000, P,    {},                                  {wall, {{P, skin}}}, St::tracking,  Ev::acquired},
        {0.2,  9000,  none, {est(Q, 100)},                       scene,               St::searching, Ev::too_small},
        {0.3,  60000, P,    {},                                  {wall, {{P, skin}}}, St::tracking,  Ev::acquired},
        {0.4,  9000,  none, {est(P, 1000)},                      {wall, {{P, skin}}}, St::tracking},
        {0.5,  9000,  none, {est(Q, 100), est({60, 50}, 1100)},  scene,               St::tracking,  Ev::recovered},
        {0.6,  9000,  none, {est(Q, 100), est({60, 50}, 100)},   scene,               St::searching, Ev::too_small},
    });
    // clang-format on
    EXPECT_EQ(played.estimated_at[5][1], cv::Point2f(60.0F, 50.0F));
    StateMachine paper_machine(paper(), paper_size);
    // clang-format off
    play(paper_machine, {
        {0.0,  0,     none, {},              {wall, {{P, skin}}}, St::searching},
        {0.1,  60000, P,    {},              {wall, {{P, skin}}}, St::tracking,  Ev::acquired},
        {0.2,  9000,  none, {est(P, 1000)},  {wall, {{P, skin}}}, St::tracking},
        {0.3,  9000,  none, {est(Q, 100)},   scene,               St::searching, Ev::too_small},
    });
    // clang-format on
}

// Failed inner point C; the recovery point `outside` (off the 160x120 image) would match
// exactly, `border` (inside, often on the first or last row or column) matches within 40 and
// is taken.
void recover_at_the_border(cv::Point2f C, cv::Point2f outside, cv::Point2f border) {
    SCOPED_TRACE(::testing::Message() << "failed at " << C);
    const Paint scene{wall, {{outside, skin}, {border, plus(skin, 40, 0, 0)}}};
    StateMachine machine(paper(), paper_size);
    // clang-format off
    const auto played = play(machine, {
        {0.0,  0,     none, {},                                {wall, {{P, skin}}}, St::searching},
        {0.1,  60000, P,    {},                                {wall, {{P, skin}}}, St::tracking, Ev::acquired},
        {0.2,  9000,  none, {est(C, 1000), est(border, 1000)}, scene,               St::tracking, Ev::recovered},
    });
    // clang-format on
    ASSERT_EQ(played.estimated_at[2].size(), 2U);
    EXPECT_EQ(played.estimated_at[2][1], border);
    for (const cv::Point2f& p : played.painted_at[2]) {
        EXPECT_TRUE(p.x >= 0 && p.y >= 0 && p.x <= 159 && p.y <= 119) << p;
    }
}

TEST(StateMachine, RecoveryPointsOutsideTheImageAreSkipped) {
    recover_at_the_border({10, 10}, {-10, 10}, {0, 10});        // left: x = -10 out, 0 in
    recover_at_the_border({10, 10}, {10, -10}, {10, 0});        // top
    recover_at_the_border({149, 60}, {169, 60}, {159, 60});     // right: 159 is the last column
    recover_at_the_border({100, 109}, {100, 129}, {100, 119});  // bottom: 119 the last row
    recover_at_the_border({150, 60}, {160, 60}, {140, 60});     // x = 160: one past the last
    recover_at_the_border({100, 110}, {100, 120}, {100, 100});  // y = 120: one past the last
}

TEST(StateMachine, NamesOfStatesAndLossReasons) {
    EXPECT_EQ(to_string(TrackerState::initializing), "initializing");
    EXPECT_EQ(to_string(TrackerState::searching), "searching");
    EXPECT_EQ(to_string(TrackerState::tracking), "tracking");
    EXPECT_EQ(to_string(TrackerState::validating), "validating");
    EXPECT_EQ(to_string(TrackerState::recovering), "recovering");
    EXPECT_EQ(to_string(LossReason::none), "none");
    EXPECT_EQ(to_string(LossReason::too_small), "too-small");
    EXPECT_EQ(to_string(LossReason::too_large), "too-large");
    EXPECT_EQ(to_string(LossReason::still), "still");
    EXPECT_EQ(to_string(LossReason::left), "left");
    EXPECT_EQ(to_string(LossReason::no_recovery_point), "no-recovery-point");
    EXPECT_EQ(to_string(LossReason::recovery_failed), "recovery-failed");
    EXPECT_EQ(to_string(LossReason::elsewhere), "elsewhere");
}

TEST(StateMachine, ColorDistanceIsTheSumOfChannelDifferences) {
    EXPECT_EQ(StateMachine::color_distance({10, 20, 30}, {40, 10, 30}), 40.0F);  // 30 + 10 + 0
    EXPECT_EQ(StateMachine::color_distance({0, 0, 0}, {255, 255, 255}), 765.0F);
}

}  // namespace
}  // namespace raypoint::core
