// SPDX-License-Identifier: MIT
// Click by depth, the timing of the press and the release as transcripts
// (test_pointer_transcript.hpp): press_hold_seconds, the release's levels (release_rise,
// release_drop, release_share), push_seconds, each timed between the frames. 10 fps rows in,
// the click state and the device command out; settings as test_click_machine.cpp's (start 5%,
// press 20%, release 10%, push 0.35 s, no hold, a constant baseline) with the part under test on.

#include <vector>

#include <gtest/gtest.h>

#include "raypoint/core/pointer_controller.hpp"
#include "test_pointer_transcript.hpp"

namespace raypoint::core {
namespace {

using test::aspect;
using test::picked;
using test::play;
using test::T;

PointerSettings depth() {
    return test::depth_pointer();
}

PointerSettings held_depth() {
    PointerSettings s = depth();
    s.click.press_hold_seconds = 0.05;
    return s;
}

// A push of +40% at 0.4 s, held into a drag by 1.2 s (10 fps rows, from the frame that picks).
std::vector<test::PointerRow> a_drag() {
    // clang-format off
    return {
        {   0,   T,       0.5,  0.5,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.280,  "pressed",    "+left"},  // +40%
        {1200,   T,       0.5,  0.5,  0.280,  "dragging",   ""},
    };
    // clang-format on
}

// Plays a drag's `rows` with `settings`, then with the rule under test turned off by `off`:
// the row `release` that let the button up then stays dragging with no command.
template <typename Off>
void play_then_stuck(PointerSettings settings, const std::vector<test::PointerRow>& rows,
                     std::size_t release, Off off) {
    PointerController with(settings, aspect);
    play(with, rows);
    off(settings);
    PointerController without(settings, aspect);
    std::vector<test::PointerRow> stuck = rows;
    stuck[release].click = "dragging";
    stuck[release].out = "";
    play(without, stuck);
}

TEST(ClickMachine, OneFrameOfAreaNeitherPressesNorReleases) {
    // press_hold_seconds 0.05: at 10 fps the rise must be at the press on two frames in a row
    // (0.1 s apart), and at the release on two frames.
    PointerController pointer(held_depth(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.340,  "rising",     ""},       // +70%, one frame
        { 500,   T,       0.5,  0.5,  0.200,  "idle",       ""},       // back: no click
        { 600,   T,       0.5,  0.5,  0.215,  "rising",     ""},       // a push
        { 700,   T,       0.5,  0.5,  0.245,  "rising",     ""},       // at the press since 700
        { 800,   T,       0.5,  0.5,  0.260,  "pressed",    "+left"},  // held 0.1 s
        { 900,   T,       0.5,  0.5,  0.200,  "pressed",    ""},       // one frame down
        {1000,   T,       0.5,  0.5,  0.260,  "pressed",    ""},       // still pressed
        {1100,   T,       0.5,  0.5,  0.215,  "pressed",    ""},       // at the release since
        {1200,   T,       0.5,  0.5,  0.205,  "refractory", "-left"},  // held 0.1 s
    });
    // clang-format on
}

TEST(ClickMachine, TheHoldCountsFromWhereARiseUnderWayCrossedThePress) {
    // press_hold_seconds 0.05 at 10 fps: the rise, 10% at 400 ms and 35% at 500, crossed 20% at
    // 440 (linearly between the frames), so it has been at the press for 0.06 s on the frame
    // that shows it. Counting from that frame waited for the next, 0.1 s later. The rise of
    // OneFrameOfAreaNeitherPressesNorReleases crosses 17 ms before its frame: held there.
    PointerController pointer(held_depth(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.220,  "rising",     ""},       // +10%
        { 500,   T,       0.5,  0.5,  0.270,  "pressed",    "+left"},  // +35%
    });
    // clang-format on
}

// jump_hold_seconds 0.06 beside press_hold_seconds 0.03, at 30 fps (rows 33-34 ms apart).
PointerSettings jump_held_depth() {
    PointerSettings s = depth();
    s.click.press_hold_seconds = 0.03;
    s.click.jump_hold_seconds = 0.06;
    return s;
}

TEST(ClickMachine, ARiseThatJumpsFromTheBaselineIsHeldLonger) {
    // A passing object taken into the region: +25% in one frame, then its share shrinking as it
    // passes. Held 0.033 s it would press (press_hold_seconds); it is under the press before
    // 0.06 s. Then a push from rest, growing over three frames, presses on press_hold_seconds.
    PointerController pointer(jump_held_depth(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.5,  0.5,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 233,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 267,   T,       0.5,  0.5,  0.250,  "rising",     ""},       // +25% in one frame
        { 300,   T,       0.5,  0.5,  0.242,  "rising",     ""},       // +21%: 0.033 s held
        { 333,   T,       0.5,  0.5,  0.236,  "rising",     ""},       // +18%: under the press
        { 367,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 800,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 833,   T,       0.5,  0.5,  0.215,  "rising",     ""},       // +7.5%
        { 867,   T,       0.5,  0.5,  0.235,  "rising",     ""},       // +17.5%
        { 900,   T,       0.5,  0.5,  0.250,  "rising",     ""},       // +25%, crossed at 878
        { 933,   T,       0.5,  0.5,  0.260,  "pressed",    "+left"},  // held 0.055 s
    });
    // clang-format on
}

TEST(ClickMachine, AJumpThatStaysPressesAfterTheJumpHold) {
    // The same jump staying up is a push that came in one frame (or a blurred one): it presses
    // once it has held 0.06 s, two frames later at 30 fps. Off (0), one frame later.
    PointerSettings settings = jump_held_depth();
    const std::vector<test::PointerRow> rows = {
        //  ms   tracker  x     y     size    click         out
        {0, T, 0.5, 0.5, picked, "inactive", ""},
        {200, T, 0.5, 0.5, 0.200, "idle", ""},
        {233, T, 0.5, 0.5, 0.200, "idle", ""},
        {267, T, 0.5, 0.5, 0.250, "rising", ""},
        {300, T, 0.5, 0.5, 0.252, "rising", ""},
        {333, T, 0.5, 0.5, 0.254, "pressed", "+left"},  // held 0.066 s
    };
    PointerController held(settings, aspect);
    play(held, rows);
    settings.click.jump_hold_seconds = 0.0;
    std::vector<test::PointerRow> off = rows;
    off[4].click = "pressed";
    off[4].out = "+left";
    off[5].out = "";
    PointerController once(settings, aspect);
    play(once, off);
}

TEST(ClickMachine, TheReleaseHoldCountsFromWhereAPullBackUnderWayCrossedIt) {
    // press_hold_seconds 0.05 at 10 fps: the pull-back is at 0.235 at 700 ms (under halfway
    // from the largest size, 0.270, to the release's level, 0.220) and at 0.205 at 800: it
    // crossed 0.220 at 750, and the release comes at 800, not at the next frame. A single frame
    // down from the top of a held push is held from its own frame
    // (OneFrameOfAreaNeitherPressesNorReleases).
    PointerController pointer(held_depth(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 500,   T,       0.5,  0.5,  0.270,  "pressed",    "+left"},
        { 600,   T,       0.5,  0.5,  0.270,  "pressed",    ""},
        { 700,   T,       0.5,  0.5,  0.235,  "pressed",    ""},       // +17.5%
        { 800,   T,       0.5,  0.5,  0.205,  "refractory", "-left"},  // +2.5%
    });
    // clang-format on
}

TEST(ClickMachine, PullingBackFromADragThatGrewTheTargetReleases) {
    // The drag carried the target where it looks bigger: pulled back, its size is still 15% over
    // the old baseline (over release_rise), but 30% under its largest while down.
    PointerSettings settings = depth();
    settings.click.release_drop = 0.25;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.230,  "rising",     ""},
        { 500,   T,       0.5,  0.5,  0.260,  "pressed",    "+left"},
        { 900,   T,       0.5,  0.5,  0.300,  "pressed",    ""},
        {1300,   T,       0.5,  0.5,  0.330,  "dragging",   ""},       // largest: 0.33
        {1400,   T,       0.5,  0.5,  0.270,  "dragging",   ""},       // 18% under it
        {1500,   T,       0.5,  0.5,  0.230,  "refractory", "-left"},  // 30% under it
    });
    // clang-format on
}

TEST(ClickMachine, ADragWhoseRiseIsMostlyGoneReleases) {
    // release_share 0.33: the drag carried the target where it looks 12.5% bigger; pulled back,
    // that is over release_rise (10%) and only 20% under the largest size (release_drop 25%),
    // but under a third of the largest rise (40%): released. Without it the drag stays down.
    PointerSettings settings = depth();
    settings.click.release_drop = 0.25;
    settings.click.release_share = 0.33;
    std::vector<test::PointerRow> drag = a_drag();
    // clang-format off
    drag.insert(drag.end(), {
        {1300,   T,       0.5,  0.5,  0.240,  "dragging",   ""},       // +20%
        {1400,   T,       0.5,  0.5,  0.225,  "refractory", "-left"},  // +12.5%
    });
    // clang-format on
    play_then_stuck(settings, drag, 6, [](PointerSettings& s) { s.click.release_share = 0.0; });
}

TEST(ClickMachine, ADragPulledBackInOneTakenOutStepReleases) {
    // release_raw_seconds 0.3: at 10 fps the pull-back is one step of -29% with the centroid
    // jumping 0.107 of the size, which the depth signal takes out as the region changing, so
    // the signal stays at the drag's level. The raw size back where the push began for 0.3 s
    // releases; without the rule the drag stays down.
    PointerSettings settings = depth();
    settings.click.glitch_step = 0.08;
    settings.click.glitch_jump = 0.10;
    settings.click.release_drop = 0.25;  // the signal must come down 12.5% for the size alone
    settings.click.release_raw_seconds = 0.3;
    std::vector<test::PointerRow> drag = a_drag();
    // clang-format off
    drag.insert(drag.end(), {
        {1300,   T,       0.53, 0.5,  0.200,  "dragging",   "rel -30 0"},  // taken out
        {1400,   T,       0.53, 0.5,  0.200,  "dragging",   ""},
        {1500,   T,       0.53, 0.5,  0.200,  "dragging",   ""},
        {1600,   T,       0.53, 0.5,  0.200,  "refractory", "-left"},  // back for 0.3 s
    });
    // clang-format on
    play_then_stuck(settings, drag, 8,
                    [](PointerSettings& s) { s.click.release_raw_seconds = 0.0; });
}

TEST(ClickMachine, AHeldRiseReachedInTimePressesAfterPushSeconds) {
    // The rise reaches the press 0.3 s in (within push_seconds, 0.35 s); holding it there ends
    // at 0.4 s, after push_seconds: still a press.
    PointerSettings settings = depth();
    settings.click.press_hold_seconds = 0.1;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 500,   T,       0.5,  0.5,  0.230,  "rising",     ""},
        { 600,   T,       0.5,  0.5,  0.245,  "rising",     ""},       // at the press, 0.3 s
        { 700,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},  // held 0.1 s, 0.4 s in
    });
    // clang-format on
}

TEST(ClickMachine, ARiseSlowerThanPushSecondsDoesNotPress) {
    // 3% a frame: the rise passes 20% 0.5 s after it passed 5%, too slow for a push. Each
    // crossing is placed between its frames: 5% two thirds of the way from 300 to 400 ms.
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.206,  "idle",       ""},       // +3%
        { 400,   T,       0.5,  0.5,  0.212,  "rising",     ""},       // +6%: began at 367
        { 500,   T,       0.5,  0.5,  0.218,  "rising",     ""},
        { 600,   T,       0.5,  0.5,  0.224,  "rising",     ""},
        { 700,   T,       0.5,  0.5,  0.230,  "rising",     ""},       // 0.33 s, under 20%
        { 800,   T,       0.5,  0.5,  0.236,  "drifting",   ""},       // 0.43 s > 0.35 s
        { 900,   T,       0.5,  0.5,  0.242,  "drifting",   ""},       // +21%: still no press
        {1000,   T,       0.5,  0.5,  0.260,  "drifting",   ""},       // +30%
        {1100,   T,       0.5,  0.5,  0.205,  "idle",       ""},       // back near the baseline
        {1200,   T,       0.5,  0.5,  0.230,  "rising",     ""},       // a real push now
        {1300,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},
    });
    // clang-format on
}

TEST(ClickMachine, APushIsTimedFromCrossingToCrossingNotFrameToFrame) {
    // 4.5% a frame at 10 fps: the rise passes 5% at 311 ms and 20% at 644 ms, 0.33 s apart,
    // within push_seconds (0.35 s), though the frames around the two crossings are 0.4 s apart.
    PointerController pointer(depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.209,  "idle",       ""},       // +4.5%
        { 400,   T,       0.5,  0.5,  0.218,  "rising",     ""},       // +9%: 5% at 311
        { 500,   T,       0.5,  0.5,  0.227,  "rising",     ""},
        { 600,   T,       0.5,  0.5,  0.236,  "rising",     ""},       // +18%
        { 700,   T,       0.5,  0.5,  0.245,  "pressed",    "+left"},  // +22.5%: 20% at 644
    });
    // clang-format on
}

TEST(ClickMachine, OneFrameBackNearTheBaselineDoesNotEndADrift) {
    // press_hold_seconds 0.05: a target leaning in drifts (+30%) with the baseline behind it;
    // the region drops a piece for one frame (+3%) and has it back. Back to IDLE on that frame,
    // the next would start a push already past the press and press a frame later. Held back
    // near the baseline for two frames, the drift ends.
    PointerController pointer(held_depth(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.206,  "idle",       ""},       // +3% a frame
        { 400,   T,       0.5,  0.5,  0.212,  "rising",     ""},
        { 500,   T,       0.5,  0.5,  0.218,  "rising",     ""},
        { 600,   T,       0.5,  0.5,  0.224,  "rising",     ""},
        { 700,   T,       0.5,  0.5,  0.230,  "rising",     ""},
        { 800,   T,       0.5,  0.5,  0.236,  "drifting",   ""},       // too slow for a push
        { 900,   T,       0.5,  0.5,  0.260,  "drifting",   ""},       // +30%
        {1000,   T,       0.5,  0.5,  0.206,  "drifting",   ""},       // +3% for one frame
        {1100,   T,       0.5,  0.5,  0.260,  "drifting",   ""},       // the piece back: no push
        {1200,   T,       0.5,  0.5,  0.265,  "drifting",   ""},
        {1300,   T,       0.5,  0.5,  0.205,  "drifting",   ""},       // back near the baseline
        {1400,   T,       0.5,  0.5,  0.205,  "idle",       ""},       // held 0.1 s
        {1500,   T,       0.5,  0.5,  0.230,  "rising",     ""},       // a real push now
        {1600,   T,       0.5,  0.5,  0.250,  "rising",     ""},
        {1700,   T,       0.5,  0.5,  0.255,  "pressed",    "+left"},
    });
    // clang-format on
}

}  // namespace
}  // namespace raypoint::core
