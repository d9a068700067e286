// SPDX-License-Identifier: MIT
// Right click, double click and scroll by depth as transcripts (test_pointer_transcript.hpp):
// 10 fps rows of the tracker's result in, the click state and the device command out. The
// size column is sqrt(area); a rise is size over the baseline, minus 1. Settings as
// test_click_machine.cpp's (start 5%, press 20%, release 10%, push 0.35 s, refractory 0.3 s,
// drag 0.8 s, no hold, clicks after 0.2 s, a constant baseline), and the gestures: right click
// after 0.5 s still, 100 wheel detents a frame width, double click within 0.6 s, a hold radius
// of 0.02 frame widths. x and y are fractions of the frame; 0.01 of x is 0.01 frame widths and
// 10 px, 0.01 of y is 0.0075 frame widths (4:3).

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

PointerSettings gestures() {
    return test::gesture_pointer();
}

TEST(ClickGestures, APushHeldStillRightClicks) {
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.495, 0.500, 0.230,  "rising",        "rel 5 0"},
        { 500,   T,       0.490, 0.500, 0.250,  "holding",       "rel -5 0"},  // undone, no button
        { 600,   T,       0.490, 0.500, 0.255,  "holding",       ""},          // still since 500
        { 900,   T,       0.492, 0.501, 0.252,  "holding",       ""},
        {1000,   T,       0.491, 0.500, 0.250,  "right_armed",   ""},   // 0.5 s still
        {1100,   T,       0.491, 0.500, 0.240,  "right_armed",   ""},   // frozen, no button
        {1200,   T,       0.491, 0.500, 0.215,  "refractory",    "+right -right"},  // pulled back
        {1300,   T,       0.491, 0.500, 0.200,  "refractory",    ""},
    });
    // clang-format on
}

TEST(ClickGestures, ARegionFlickeringWhileHeldIsStill) {
    // The tracker's region of a held hand drops a piece every other frame: 4% of the size,
    // over hold_rise (3%). Its largest size within hold_flicker_seconds (0.1 s) is still for
    // 0.5 s: a right click. Sized frame by frame (0) it is a right click too, at this frame
    // rate by another rule: each drop is under the jump of 9% a frame at 10 fps, and each
    // return a step over hold_rise back to the size it left (test_click_hold.cpp). Without
    // either, each flicker restarts the stillness and the pull-back left-clicks.
    // clang-format off
    const std::vector<test::PointerRow> flicker = {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 600,   T,       0.500, 0.500, 0.240,  "holding",       ""},   // -4%
        { 700,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.240,  "holding",       ""},
        { 900,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.240,  "right_armed",   ""},   // 0.5 s at 0.250
        {1100,   T,       0.500, 0.500, 0.250,  "right_armed",   ""},
        {1200,   T,       0.500, 0.500, 0.215,  "refractory",    "+right -right"},
    };
    // clang-format on
    PointerController pointer(gestures(), aspect);
    play(pointer, flicker);
    PointerSettings framewise = gestures();
    framewise.click.hold_flicker_seconds = 0.0;
    PointerController by_frame(framewise, aspect);
    play(by_frame, flicker);
}

TEST(ClickGestures, AHeldPushThatRestsBeforeMovingStillDrags) {
    // Still for 0.6 s (right click armed), then moved sideways: a drag, not a right click. A
    // hand often rests a moment before it starts to drag.
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.600, 0.400, 0.200,  "idle",          ""},
        { 300,   T,       0.600, 0.400, 0.205,  "idle",          ""},
        { 400,   T,       0.600, 0.400, 0.240,  "rising",        ""},
        { 500,   T,       0.600, 0.400, 0.260,  "holding",       ""},
        { 900,   T,       0.600, 0.400, 0.260,  "holding",       ""},
        {1100,   T,       0.590, 0.400, 0.255,  "right_armed",   ""},   // 0.01: within
        {1200,   T,       0.570, 0.400, 0.255,  "dragging",      "+left"},
        {1300,   T,       0.550, 0.400, 0.255,  "dragging",      "rel 20 0"},
        {1400,   T,       0.550, 0.400, 0.210,  "refractory",    "-left"},
    });
    // clang-format on
}

TEST(ClickGestures, AQuickPushClicksWhenPulledBack) {
    // With right click on, the left press waits for the gesture to show: pulled back, it is a
    // click, press and release in one command where the push began.
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 600,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 700,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left"},
        { 800,   T,       0.510, 0.500, 0.200,  "refractory",    "rel -10 0"},  // moves again
    });
    // clang-format on
}

TEST(ClickGestures, ASlowLeftClickIsNotARightClick) {
    // Pressed 0.3 s in, still growing for 0.4 s, held 0.2 s, pulled back over 0.4 s: 1 s from
    // the press to the release, but never still for 0.5 s (the size changes by more than
    // hold_rise within each 0.5 s): a left click.
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.215,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 600,   T,       0.500, 0.500, 0.245,  "holding",       ""},   // +22.5%, 0.3 s in
        { 700,   T,       0.500, 0.500, 0.255,  "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.265,  "holding",       ""},   // +8% of 0.245: restarts
        { 900,   T,       0.500, 0.500, 0.275,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.285,  "holding",       ""},   // +7.5% of 0.265
        {1100,   T,       0.500, 0.500, 0.285,  "holding",       ""},
        {1200,   T,       0.500, 0.500, 0.285,  "holding",       ""},
        {1300,   T,       0.500, 0.500, 0.265,  "holding",       ""},   // -7%: restarts
        {1400,   T,       0.500, 0.500, 0.245,  "holding",       ""},
        {1500,   T,       0.500, 0.500, 0.225,  "holding",       ""},
        {1600,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left"},
    });
    // clang-format on
}

TEST(ClickGestures, ASlowClicksRoundedTopIsNotStill) {
    // A push easing in and out: its top stays within 5% of where HOLDING began for 0.5 s, but
    // not within hold_rise (0.03), so the pull-back left-clicks. With the band at 0.05 (the
    // paper preset's) the same push is held still for right_seconds and right-clicks.
    // clang-format off
    const std::vector<test::PointerRow> top = {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.225,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 600,   T,       0.500, 0.500, 0.256,  "holding",       ""},
        { 700,   T,       0.500, 0.500, 0.260,  "holding",       ""},   // +4%: restarts
        { 800,   T,       0.500, 0.500, 0.262,  "holding",       ""},
        { 900,   T,       0.500, 0.500, 0.260,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.256,  "holding",       ""},
        {1100,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // -3.8%: restarts
        {1200,   T,       0.500, 0.500, 0.240,  "holding",       ""},
        {1300,   T,       0.500, 0.500, 0.220,  "refractory",    "+left -left"},
    };
    // clang-format on
    PointerController pointer(gestures(), aspect);
    play(pointer, top);
    PointerSettings wide = gestures();
    wide.click.hold_rise = 0.05;
    PointerController widely(wide, aspect);
    std::vector<test::PointerRow> armed = top;
    armed[9].click = "right_armed";  // 0.5 s within 5% of 0.250
    armed[10].click = "right_armed";
    armed[11].click = "right_armed";
    armed[12].out = "+right -right";
    play(widely, armed);
}

TEST(ClickGestures, AHeldPushMovingSidewaysDrags) {
    // Moved 0.03 frame widths sideways: farther than the hold radius, more sideways than up, a
    // drag. Its press goes down where the push began; the motion follows from the next frame.
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // one frame is enough
        { 500,   T,       0.490, 0.505, 0.250,  "holding",       ""},   // 0.011: within
        { 600,   T,       0.470, 0.510, 0.250,  "dragging",      "+left"},
        { 700,   T,       0.450, 0.510, 0.250,  "dragging",      "rel 20 0"},
        { 800,   T,       0.440, 0.510, 0.210,  "refractory",    "rel 10 0 -left"},
    });
    // clang-format on
}

TEST(ClickGestures, AHeldPushMovingUpScrollsUp) {
    // 0.04 of y up is 0.03 frame widths: 3 detents (360 in 120ths) at 100 a frame width; x and
    // y stay frozen, and pulling back ends it without a button.
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 500,   T,       0.500, 0.460, 0.250,  "scrolling",     "wheel 3 hires 360"},
        { 600,   T,       0.502, 0.440, 0.250,  "scrolling",     "wheel 1 hires 180"},  // 4.5
        { 700,   T,       0.502, 0.436, 0.250,  "scrolling",     "hires 36"},           // 4.8
        { 800,   T,       0.502, 0.432, 0.250,  "scrolling",     "wheel 1 hires 36"},   // 5.1
        { 900,   T,       0.502, 0.442, 0.250,  "scrolling",     "wheel -1 hires -90"},  // back
        {1000,   T,       0.502, 0.442, 0.210,  "refractory",    ""},
        {1100,   T,       0.512, 0.442, 0.200,  "refractory",    "rel -10 0"},
    });
    // clang-format on
}

TEST(ClickGestures, WithoutScrollAHeldPushMovingDownDrags) {
    // Without scroll_gain, moving a held push up or down drags.
    PointerSettings s = gestures();
    s.click.scroll_gain = 0.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 500,   T,       0.500, 0.540, 0.250,  "dragging",      "+left"},
        { 600,   T,       0.500, 0.560, 0.250,  "dragging",      "rel 0 15"},
    });
    // clang-format on
}

TEST(ClickGestures, ScrollAloneStillDragsByHolding) {
    // Scroll on, right click off: a push held still becomes a drag after drag_seconds, as
    // without the gestures (the press where the push began, then free motion).
    PointerSettings s = gestures();
    s.click.right_seconds = 0.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1100,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1200,   T,       0.500, 0.500, 0.250,  "dragging",      "+left"},  // 0.8 s
        {1300,   T,       0.490, 0.500, 0.250,  "dragging",      "rel 10 0"},
    });
    // clang-format on
}

TEST(ClickGestures, LosingTheTargetWhileArmedClicksNothing) {
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 900,   T,       0.500, 0.500, 0.250,  "right_armed",   ""},
        {1000,   S,       0.0,   0.0,   0.0,    "inactive",      ""},
    });
    // clang-format on
}

TEST(ClickGestures, AOneFrameGlitchWhileHeldNeitherScrollsNorClicks) {
    // press_hold_seconds 0.05: one frame of a smaller area does not end the hold, so the
    // right click is still armed and comes at the pull-back.
    PointerSettings s = gestures();
    s.click.press_hold_seconds = 0.05;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 600,   T,       0.500, 0.500, 0.200,  "holding",       ""},   // one frame back
        { 700,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1200,   T,       0.500, 0.500, 0.250,  "right_armed",   ""},   // 0.5 s since 700
        {1300,   T,       0.500, 0.500, 0.210,  "right_armed",   ""},   // back for 0.05 s
        {1400,   T,       0.500, 0.500, 0.210,  "refractory",    "+right -right"},
    });
    // clang-format on
}

PointerSettings gestures_with_glitches() {
    PointerSettings s = gestures();
    s.click.glitch_jump = 0.1;
    s.click.release_drop = 0.25;
    s.click.hold_radius = 0.05;
    return s;
}

// A push from 0.200 to 0.260 held still until the right click is armed.
void hold_a_push(PointerController& pointer) {
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.260,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.260,  "right_armed",   ""},
    });
    // clang-format on
}

TEST(ClickGestures, APullBackWhoseLastStepIsTakenOutStillRightClicks) {
    // The pull-back's last frame shrinks the region by 27% with its centroid 0.13 of the size
    // away: the depth signal takes the step out as the region changing and stays at 0.225, a
    // rise of 12.5%. The target's own size is back where the push began: the pull-back.
    PointerController pointer(gestures_with_glitches(), aspect);
    hold_a_push(pointer);
    // clang-format off
    play(pointer, {
        {1100,   T,       0.500, 0.500, 0.225,  "right_armed",   ""},   // -13.5%
        {1200,   T,       0.530, 0.500, 0.165,  "refractory",    "rel -30 0 +right -right"},
    });
    // clang-format on
}

TEST(ClickGestures, ARegionFlickerAtTheTopOfAHeldPushDoesNotRelease) {
    // The same small size for one frame with the push still at its peak: the region dropped a
    // piece, the signal stays at the peak, and the right click waits for the pull-back.
    PointerController pointer(gestures_with_glitches(), aspect);
    hold_a_push(pointer);
    // clang-format off
    play(pointer, {
        {1100,   T,       0.530, 0.500, 0.190,  "right_armed",   ""},   // -27%, taken out
        {1200,   T,       0.500, 0.500, 0.260,  "right_armed",   ""},   // and given back
        {1300,   T,       0.500, 0.500, 0.200,  "refractory",    "+right -right"},
    });
    // clang-format on
}

TEST(ClickGestures, ARegionThatTakesInAPieceWhileHeldDoesNotScroll) {
    // hold_settle_seconds 0.2: the held push's region takes in a piece below the hand (+38%, the
    // centroid 0.03 frame widths down: taken out), and the smoothed position goes on following
    // it down for two frames, 0.06 frame widths in all, past the hold radius of 0.05. The
    // hold counts from where the step left the position: no scroll, and the right click comes
    // at the pull-back.
    PointerSettings s = gestures_with_glitches();
    s.click.hold_settle_seconds = 0.2;
    PointerController pointer(s, aspect);
    hold_a_push(pointer);
    // clang-format off
    play(pointer, {
        {1100,   T,       0.500, 0.540, 0.360,  "right_armed",   ""},   // absorbed
        {1200,   T,       0.500, 0.570, 0.360,  "right_armed",   ""},
        {1300,   T,       0.500, 0.580, 0.360,  "right_armed",   ""},
        {1400,   T,       0.500, 0.580, 0.360,  "right_armed",   ""},
        {1500,   T,       0.500, 0.580, 0.290,  "refractory",    "+right -right"},  // back
    });
    // clang-format on
}

// At 10 fps the depth signal leaves a step of up to 24% in as a push's possible growth (3x
// glitch_step): position unsmoothed, so the step's centroid jump is passed on at once.
const OutputSettings unsmoothed{SmoothingKind::ema, 0.0};

TEST(ClickGestures, ARegionStepLeftInAt10FpsWhileHeldDoesNotScroll) {
    // The held push's region takes in a piece below the hand: +20% (left in) with the centroid
    // 0.06 frame widths down, 0.23 of the size (past glitch_jump, under its 10 fps allowance).
    // Past the hold radius of 0.05, but a held push does not grow 8% in a frame: the region
    // did, and the hold leaves its jump out.
    PointerController pointer(gestures_with_glitches(), aspect, unsmoothed);
    hold_a_push(pointer);
    // clang-format off
    play(pointer, {
        {1100,   T,       0.500, 0.580, 0.312,  "right_armed",   ""},   // +20%, 0.06 down
        {1200,   T,       0.500, 0.580, 0.312,  "right_armed",   ""},
        {1300,   T,       0.500, 0.580, 0.200,  "refractory",    "+right -right"},
    });
    // clang-format on
}

TEST(ClickGestures, AHeldPushMovingOnAfterARegionStepAt10FpsScrolls) {
    // The same step, then the hand moves on down 0.06 frame widths: the hold left out the
    // step's jump only, and the motion after it scrolls.
    PointerController pointer(gestures_with_glitches(), aspect, unsmoothed);
    hold_a_push(pointer);
    // clang-format off
    play(pointer, {
        {1100,   T,       0.500, 0.580, 0.312,  "right_armed",   ""},
        {1200,   T,       0.500, 0.620, 0.312,  "right_armed",   ""},   // 0.03 on
        {1300,   T,       0.500, 0.660, 0.312,  "scrolling",     "wheel -6 hires -720"},
    });
    // clang-format on
}

}  // namespace
}  // namespace raypoint::core
