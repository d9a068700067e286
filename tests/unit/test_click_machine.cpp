// SPDX-License-Identifier: MIT
// Click by depth as transcripts (test_pointer_transcript.hpp): 10 fps rows of the tracker's
// result in, the click state and the device command out. The size column is sqrt(area); a rise
// is size over the baseline, minus 1. Settings: start 5%, press 20%, release 10%, push 0.35 s,
// refractory 0.3 s, drag 0.8 s, clicks allowed after 0.2 s of tracking, and a baseline held
// constant (time constant 1000 s) except where a test says otherwise. The hold, the release's
// rules and the push's timing are in test_click_timing.cpp.

#include <gtest/gtest.h>

#include "raypoint/core/pointer_controller.hpp"
#include "test_pointer_transcript.hpp"

namespace raypoint::core {
namespace {

using test::aspect;
using test::picked;
using test::play;
using test::S;
using test::T;

PointerSettings depth() {
    return test::depth_pointer();
}

TEST(ClickMachine, PushPressesAndPullingBackReleases) {
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   S,       0.0,  0.0,  0.0,    "inactive",   ""},
        { 100,   T,       0.0,  0.0,  picked, "inactive",   ""},       // tracking from here
        { 200,   T,       0.5,  0.5,  0.200,  "inactive",   ""},       // 0.1 s: too soon
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},       // 0.2 s: allowed
        { 400,   T,       0.5,  0.5,  0.200,  "idle",       ""},       // the push begins after
        { 500,   T,       0.5,  0.5,  0.215,  "rising",     ""},       // +7.5%
        { 600,   T,       0.5,  0.5,  0.230,  "rising",     ""},       // +15%
        { 700,   T,       0.5,  0.5,  0.245,  "pressed",    "+left"},  // +22.5%, 0.3 s in
        { 800,   T,       0.5,  0.5,  0.260,  "pressed",    ""},
        { 900,   T,       0.5,  0.5,  0.230,  "pressed",    ""},       // +15%: over the release
        {1000,   T,       0.5,  0.5,  0.215,  "refractory", "-left"},  // +7.5%
        {1100,   T,       0.5,  0.5,  0.200,  "refractory", ""},
        {1299,   T,       0.5,  0.5,  0.200,  "refractory", ""},
        {1301,   T,       0.5,  0.5,  0.200,  "idle",       ""},
    });
    // clang-format on
}

TEST(ClickMachine, TheBaselineFollowsASlowApproach) {
    // The default time constant (1 s). The target comes 45% closer over 2 s (sqrt(area) 0.2 to
    // 0.29, then 0.3) and stays: no press, and once the baseline has caught up, a push from the
    // new distance clicks.
    PointerSettings s = depth();
    s.click.baseline_seconds = 1.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out         rise, baseline
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.209,  "idle",       ""},        // +4.5%, 0.2016
        { 600,   T,       0.5,  0.5,  0.218,  "rising",     ""},        // +8.1%: 5% at 460 ms
        { 800,   T,       0.5,  0.5,  0.227,  "rising",     ""},        // +12.6%, 0.34 s in
        {1000,   T,       0.5,  0.5,  0.236,  "drifting",   ""},        // +17%, 0.54 s in; 0.2079
        {1400,   T,       0.5,  0.5,  0.254,  "drifting",   ""},
        {1800,   T,       0.5,  0.5,  0.272,  "drifting",   ""},
        {2200,   T,       0.5,  0.5,  0.290,  "drifting",   ""},        // +21%, 0.256
        {2400,   T,       0.5,  0.5,  0.300,  "drifting",   ""},
        {3000,   T,       0.5,  0.5,  0.300,  "drifting",   ""},        // +14%
        {3500,   T,       0.5,  0.5,  0.300,  "drifting",   ""},        // +7%
        {4000,   T,       0.5,  0.5,  0.300,  "idle",       ""},        // +4.2%, 0.293
        {4500,   T,       0.5,  0.5,  0.300,  "idle",       ""},
        {4600,   T,       0.5,  0.5,  0.330,  "rising",     ""},        // +12%
        {4700,   T,       0.5,  0.5,  0.375,  "pressed",    "+left"},   // +27%
    });
    // clang-format on
    EXPECT_GT(pointer.click_machine().baseline(), 0.29);
}

TEST(ClickMachine, HeldPushedBecomesADragThatMoves) {
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.5,  picked, "inactive",  ""},
        { 200,   T,       0.500, 0.5,  0.200,  "idle",      ""},
        { 300,   T,       0.500, 0.5,  0.250,  "pressed",   "+left"},    // one frame is enough
        { 400,   T,       0.490, 0.5,  0.250,  "pressed",   ""},         // frozen
        {1000,   T,       0.480, 0.5,  0.250,  "pressed",   ""},         // 0.7 s down
        {1100,   T,       0.470, 0.5,  0.250,  "dragging",  "rel 10 0"}, // 0.8 s: moves again
        {1200,   T,       0.450, 0.5,  0.230,  "dragging",  "rel 20 0"},
        {1300,   T,       0.440, 0.5,  0.210,  "refractory","rel 10 0 -left"},  // motion first
        {1400,   T,       0.430, 0.5,  0.200,  "refractory","rel 10 0"},
    });
    // clang-format on
}

TEST(ClickMachine, SecondPushInsideTheRefractoryTimeIsIgnored) {
    // After a release a press needs both refractory_seconds and the rise back under start_rise.
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},
        { 400,   T,       0.5,  0.5,  0.210,  "refractory", "-left"},
        { 500,   T,       0.5,  0.5,  0.200,  "refractory", ""},       // settled, but 0.1 s
        { 600,   T,       0.5,  0.5,  0.250,  "refractory", ""},       // a push 0.2 s after
        { 700,   T,       0.5,  0.5,  0.260,  "refractory", ""},       // 0.3 s, not settled
        { 800,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 900,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},  // now it counts
    });
    // clang-format on
}

TEST(ClickMachine, MotionDuringThePushIsUndoneAndFrozen) {
    // The centroid drifts 0.0021 widths (2.1 px) a frame while the push rises: the press takes
    // the 4 px emitted since the push began back, and holds its own frame's, so the button goes
    // down where the push began. Motion resumes with the release, before it.
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,    0.5,  picked, "inactive",   ""},
        { 200,   T,       0.5000, 0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.4979, 0.5,  0.200,  "idle",       "rel 2 0"},         // 2.1
        { 400,   T,       0.4958, 0.5,  0.220,  "rising",     "rel 2 0"},         // 2.2
        { 500,   T,       0.4937, 0.5,  0.230,  "rising",     "rel 2 0"},         // 2.3
        { 600,   T,       0.4916, 0.5,  0.250,  "pressed",    "rel -4 0 +left"},
        { 700,   T,       0.4800, 0.5,  0.260,  "pressed",    ""},
        { 800,   T,       0.4779, 0.5,  0.210,  "refractory", "rel 2 0 -left"},   // 2.1
    });
    // clang-format on
}

TEST(ClickMachine, AbsoluteModeReturnsToWhereThePushBegan) {
    PointerSettings s = depth();
    s.motion.mode = PointerMode::absolute;
    s.motion.absolute_max = 1000;
    s.motion.active_left = 0.0;
    s.motion.active_right = 1.0;
    s.motion.active_top = 0.0;
    s.motion.active_bottom = 1.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.5,  picked, "inactive",   ""},
        { 200,   T,       0.50,  0.5,  0.200,  "idle",       "abs 500 500"},
        { 300,   T,       0.49,  0.5,  0.220,  "rising",     "abs 510 500"},
        { 400,   T,       0.48,  0.5,  0.250,  "pressed",    "abs 500 500 +left"},
        { 500,   T,       0.47,  0.5,  0.260,  "pressed",    ""},
        { 600,   T,       0.47,  0.5,  0.210,  "refractory", "abs 530 500 -left"},
    });
    // clang-format on
}

TEST(ClickMachine, LosingTheTargetReleasesTheButton) {
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},
        { 400,   S,       0.0,  0.0,  0.0,    "inactive",   "-left"},
        { 500,   S,       0.0,  0.0,  0.0,    "inactive",   ""},
        { 600,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 700,   T,       0.5,  0.5,  0.250,  "inactive",   ""},       // 0.1 s: not yet
        { 800,   T,       0.5,  0.5,  0.250,  "idle",       ""},       // its size is the baseline
        { 900,   T,       0.5,  0.5,  0.250,  "idle",       ""},
        {1000,   T,       0.5,  0.5,  0.310,  "pressed",    "+left"},  // +24%
        {1100,   T,       0.5,  0.5,  picked, "inactive",   "-left"},  // area unknown: no target
    });
    // clang-format on
    EXPECT_FALSE(pointer.is_down(Button::left));
}

TEST(ClickMachine, NoClickBeforeMinTrackingSeconds) {
    PointerSettings s = depth();
    s.safety.min_tracking_seconds = 1.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 100,   T,       0.5,  0.5,  0.200,  "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.260,  "inactive",   ""},       // a push: too soon
        { 300,   T,       0.5,  0.5,  0.200,  "inactive",   ""},
        { 900,   T,       0.5,  0.5,  0.200,  "inactive",   ""},
        { 950,   T,       0.5,  0.5,  0.260,  "inactive",   ""},       // pushed when allowed...
        {1000,   T,       0.5,  0.5,  0.260,  "idle",       ""},       // ...is not a push
        {1100,   T,       0.5,  0.5,  0.200,  "idle",       ""},       // pulling back: nothing
        {1200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
    });
    // clang-format on
}

TEST(ClickMachine, ReleaseAllReleasesAndStartsOver) {
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.5,  picked, "inactive",  ""},
        { 200,   T,       0.500, 0.5,  0.200,  "idle",      ""},
        { 300,   T,       0.500, 0.5,  0.250,  "pressed",   "+left"},
    });
    // clang-format on
    EXPECT_EQ(test::format(pointer.release_all()), "-left");
    EXPECT_EQ(test::format(pointer.release_all()), "");  // nothing down any more
    // clang-format off
    play(pointer, {
        { 400,   T,       0.400, 0.5,  0.250,  "inactive",  ""},         // no jump after a pause
        { 500,   T,       0.390, 0.5,  0.250,  "inactive",  "rel 10 0"},
        { 600,   T,       0.390, 0.5,  0.320,  "idle",      ""},         // 0.2 s: size = baseline
    });
    // clang-format on
}

TEST(ClickMachine, ModeOffNeverClicks) {
    PointerSettings s = depth();
    s.click.mode = ClickMode::off;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, nullptr,      ""},
        { 200,   T,       0.5,  0.5,  0.200,  nullptr,      ""},
        { 300,   T,       0.5,  0.5,  0.300,  "inactive",   ""},
    });
    // clang-format on
}

TEST(ClickMachine, ReleasesByItselfWhenTheTargetGoesOrIsNotReady) {
    // The machine on its own, without the controller's guard: a press, then no target.
    ClickSettings settings;  // the defaults (press at +15% within 0.25 s), pressing at once
    settings.press_hold_seconds = 0.0;
    settings.jump_hold_seconds = 0.0;
    ClickMachine machine{settings};
    EXPECT_EQ(machine.step(0, 0.2, true).state, ClickState::idle);
    const ClickStep press = machine.step(100'000, 0.26, true);
    EXPECT_TRUE(press.press);
    // The rise passed start_rise (5%) a sixth of the way to this frame's 30%.
    EXPECT_EQ(press.push_began, 16'666);
    const ClickStep gone = machine.step(200'000, std::nullopt, true);
    EXPECT_TRUE(gone.release);
    EXPECT_EQ(gone.state, ClickState::inactive);
    EXPECT_FALSE(machine.step(300'000, std::nullopt, true).release);  // only once
    // Down again, then not ready (after release_all the controller starts the wait over).
    EXPECT_EQ(machine.step(400'000, 0.2, true).state, ClickState::idle);
    EXPECT_TRUE(machine.step(500'000, 0.26, true).press);
    const ClickStep waiting = machine.step(600'000, 0.26, false);
    EXPECT_TRUE(waiting.release);
    EXPECT_EQ(waiting.state, ClickState::inactive);
    EXPECT_FALSE(machine.release_all());  // nothing down any more
}

TEST(ClickMachine, EveryStateHasItsOwnName) {
    const ClickState states[] = {ClickState::inactive,  ClickState::idle,    ClickState::rising,
                                 ClickState::drifting,  ClickState::pressed, ClickState::dragging,
                                 ClickState::refractory};
    for (const ClickState a : states) {
        EXPECT_NE(to_string(a), "?");
        for (const ClickState b : states) {
            if (a != b) {
                EXPECT_NE(to_string(a), to_string(b));
            }
        }
    }
}

}  // namespace
}  // namespace raypoint::core
