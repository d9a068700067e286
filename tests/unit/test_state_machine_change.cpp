// SPDX-License-Identifier: MIT
// SEARCHING's pick of what changed since the last quiet frame (TrackingSettings::change_seconds):
// a target that came in and stopped, missed by the search of two frames' difference, as
// transcripts. Working image 160x120 (state_machine_testing.hpp): search above 57,600, quiet at
// or under 4,800.

#include <vector>

#include <gtest/gtest.h>

#include "state_machine_testing.hpp"

namespace raypoint::core {
namespace {

using test::play;
using Ev = test::Event;
using St = TrackerState;
using namespace test::machine;

const cv::Point2f Q(90.0F, 40.0F);  // where the change is

TrackingSettings with_change(double seconds) {
    TrackingSettings s = paper();
    s.change_seconds = seconds;
    return s;
}

TEST(StateMachine, ATargetThatCameInAndStoppedIsPickedWhereTheSceneChanged) {
    // Quiet frames are kept (from the first searched one) until something moves; the hand comes in
    // (a pick whose estimate is too small: lost) and stops. 0.2 s into the quiet the change is
    // looked for once, and the pick is there; its estimate comes with the next frame.
    StateMachine machine(with_change(0.2), paper_size);
    // clang-format off
    const auto played = play(machine, {
        //  t    movement  detect  estimate()       paint         -> state     event   near  change
        {0.0,   0,        none,   {},              {wall, {}},   St::searching},
        {0.1,   4800,     none,   {},              {wall, {}},   St::searching},
        {0.2,   60000,    P,      {},              {skin, {}},   St::tracking,  Ev::acquired},
        {0.3,   9000,     none,   {est(P, 100)},   {skin, {}},   St::searching, Ev::too_small},
        {0.4,   0,        none,   {},              {skin, {}},   St::searching, Ev::none, none, Q},
        {0.5,   0,        none,   {},              {skin, {}},   St::searching, Ev::none, none, Q},
        {0.6,   0,        none,   {},              {skin, {}},   St::tracking,  Ev::acquired, none, Q},
        {0.7,   0,        none,   {est(Q, 1000)},  {skin, {}},   St::tracking},
    });
    // clang-format on
    const std::vector<bool> kept{false, true, false, false, false, false, false, false};
    const std::vector<bool> asked{false, false, false, false, false, false, true, false};
    EXPECT_EQ(played.kept_quiet, kept);
    EXPECT_EQ(played.asked_change, asked);
    EXPECT_EQ(played.results[6].estimate.centroid, Q);
    EXPECT_EQ(played.estimated_at[7], std::vector<cv::Point2f>{Q});
}

TEST(StateMachine, MovementThatLeftNothingBehindStartsTheQuietFramesAgain) {
    // Movement over the idle threshold restarts the quiet (0.3 s); with no change at 0.6 s (the
    // movement passed through) the next quiet frame is kept, and no change is looked for until
    // something moves again.
    StateMachine machine(with_change(0.2), paper_size);
    // clang-format off
    const auto played = play(machine, {
        {0.0,   0,        none,   {},   {wall, {}},   St::searching},
        {0.1,   60000,    none,   {},   {wall, {}},   St::searching},  // no mass: nothing picked
        {0.2,   0,        none,   {},   {wall, {}},   St::searching},
        {0.3,   4801,     none,   {},   {wall, {}},   St::searching},
        {0.4,   0,        none,   {},   {wall, {}},   St::searching},
        {0.5,   0,        none,   {},   {wall, {}},   St::searching},
        {0.6,   0,        none,   {},   {wall, {}},   St::searching},
        {0.7,   0,        none,   {},   {wall, {}},   St::searching},
        {0.8,   0,        none,   {},   {wall, {}},   St::searching},
    });
    // clang-format on
    const std::vector<bool> kept{false, false, false, false, false, false, false, true, true};
    const std::vector<bool> asked{false, false, false, false, false, false, true, false, false};
    EXPECT_EQ(played.kept_quiet, kept);
    EXPECT_EQ(played.asked_change, asked);
}

TEST(StateMachine, ATargetThatIsSceneryIsDroppedForTheChange) {
    // The pick of a hand coming in is estimated as the wall beside it (area 3,000), whose
    // colour validates. 0.2 s into the quiet the change is at Q; the target's inner point
    // looks as it did in the quiet frame (wall, within the tolerance), and the region at Q is
    // another (area 800, elsewhere): Q is picked. The same with the target's inner point
    // changed since the quiet frame (a target that came in) keeps it.
    for (const bool scenery : {true, false}) {
        SCOPED_TRACE(scenery ? "scenery" : "came in");
        const cv::Vec3f quiet = scenery ? plus(wall, 10, 0, 0) : skin;
        StateMachine machine(with_change(0.2), paper_size);
        const Ev switched = scenery ? Ev::acquired : Ev::none;
        // clang-format off
        const auto played = play(machine, {
            {0.0, 0,     none, {},                              {wall, {}}, St::searching},
            {0.1, 60000, P,    {},                              {wall, {}}, St::tracking, Ev::acquired},
            {0.2, 0,     none, {est(P, 3000)},                  {wall, {}}, St::tracking, Ev::none, none, Q, quiet},
            {0.3, 0,     none, {est(P, 3000)},                  {wall, {}}, St::tracking, Ev::none, none, Q, quiet},
            {0.4, 0,     none, scenery ? std::vector<Estimate>{est(P, 3000), est(Q, 800)}
                                       : std::vector<Estimate>{est(P, 3000)},
                                                                {wall, {}}, St::tracking, switched, none, Q, quiet},
        });
        // clang-format on
        EXPECT_EQ(played.asked_change[4], true);
        if (scenery) {
            EXPECT_EQ(played.estimated_at[4], (std::vector<cv::Point2f>{P, Q}));
            EXPECT_EQ(played.results[4].estimate.centroid, Q);
        } else {
            EXPECT_EQ(played.estimated_at[4], std::vector<cv::Point2f>{P});
        }
    }
}

TEST(StateMachine, ThePaperPresetNeverLooksForAChange) {
    StateMachine machine(paper(), paper_size);
    // clang-format off
    const auto played = play(machine, {
        {0.0,   0,        none,   {},   {wall, {}},   St::searching},
        {0.1,   60000,    none,   {},   {wall, {}},   St::searching},
        {0.2,   0,        none,   {},   {wall, {}},   St::searching, Ev::none, none, Q},
        {0.8,   0,        none,   {},   {wall, {}},   St::searching, Ev::none, none, Q},
    });
    // clang-format on
    for (std::size_t i = 0; i < played.kept_quiet.size(); ++i) {
        EXPECT_FALSE(played.kept_quiet[i]) << i;
        EXPECT_FALSE(played.asked_change[i]) << i;
    }
}

}  // namespace
}  // namespace raypoint::core
