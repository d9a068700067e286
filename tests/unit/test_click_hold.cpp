// SPDX-License-Identifier: MIT
// A held push's stillness and its way back, as transcripts (test_pointer_transcript.hpp; the
// settings of test_click_gestures.cpp: right click after 0.5 s still, hold_rise 3%,
// hold_flicker_seconds 0.1 s, release 10% over the baseline of 0.200).

#include <gtest/gtest.h>

#include "raypoint/core/pointer_controller.hpp"
#include "test_pointer_transcript.hpp"

namespace raypoint::core {
namespace {

using test::aspect;
using test::picked;
using test::play;
using test::T;

// Picked, and a push from 0.200 pressed at 0.250 (HOLDING) at 0.5 s.
PointerController pressed(const PointerSettings& settings) {
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.250,  "holding",       ""},
    });
    // clang-format on
    return pointer;
}

TEST(ClickHold, ARegionThatTakesInAPieceForAFewFramesWhileHeldIsStill) {
    // The held hand's region takes in a piece for two frames: +10% in one frame, more than a
    // push grows at 10 fps (hold_rise per 1/30 s), then back to the size it jumped from. Still
    // since 0.5 s, and at that size for 0.2 s (twice hold_flicker_seconds) from 1.1 s: right
    // click. Without the way back to the size it left, the stillness would count from 0.9 s and
    // the pull-back at 1.2 s would left-click.
    PointerController pointer = pressed(test::gesture_pointer());
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        { 600,   T,       0.500, 0.500, 0.275,  "holding",       ""},   // +10%: a jump
        { 700,   T,       0.500, 0.500, 0.275,  "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // the peak held 0.1 s
        { 900,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // back: still since 500
        {1000,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // 0.1 s at this size
        {1100,   T,       0.500, 0.500, 0.250,  "right_armed",   ""},
        {1200,   T,       0.500, 0.500, 0.215,  "refractory",    "+right -right"},
    });
    // clang-format on
}

TEST(ClickHold, ASizeLeftGraduallyIsNoSizeToComeBackTo) {
    // The held push comes 5% closer in a frame (under the jump of 9% a frame at 10 fps: the
    // hand moved, as a push does), holds, and eases back to the size it was pressed at over two
    // frames, each under hold_rise. Left and come back to gradually: the stillness counts from
    // the return, and the pull-back left-clicks.
    PointerController pointer = pressed(test::gesture_pointer());
    // clang-format off
    play(pointer, {
        { 600,   T,       0.500, 0.500, 0.262,  "holding",       ""},   // +4.8%
        { 700,   T,       0.500, 0.500, 0.262,  "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.262,  "holding",       ""},
        { 900,   T,       0.500, 0.500, 0.256,  "holding",       ""},   // -2.3%
        {1000,   T,       0.500, 0.500, 0.250,  "holding",       ""},   // -2.3%: still since here
        {1100,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1200,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1300,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left"},
    });
    // clang-format on
}

TEST(ClickHold, ASizeCreptAwayFromAndJumpedBackToIsStillTheHold) {
    // At 30 fps the held push's region creeps 4% larger over a few frames (each under hold_rise
    // a frame: the region taking in a piece bit by bit, or the hand) and snaps back to the size
    // it was pressed at in one frame. That step is the region dropping what it crept into:
    // still since 0.5 s, at that size 0.2 s from 0.767 s, right click. A size left gradually and
    // come back to gradually is no hold (the test above); without the step, the stillness
    // would count from 0.767 s and the pull-back at 1.033 s would left-click.
    PointerController pointer = pressed(test::gesture_pointer());
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        { 533,   T,       0.500, 0.500, 0.2525, "holding",       ""},
        { 567,   T,       0.500, 0.500, 0.2550, "holding",       ""},
        { 600,   T,       0.500, 0.500, 0.2580, "holding",       ""},   // +3.2%: left, crept
        { 633,   T,       0.500, 0.500, 0.2600, "holding",       ""},
        { 667,   T,       0.500, 0.500, 0.2595, "holding",       ""},
        { 700,   T,       0.500, 0.500, 0.2500, "holding",       ""},   // -3.7%: a jump
        { 733,   T,       0.500, 0.500, 0.2500, "holding",       ""},
        { 767,   T,       0.500, 0.500, 0.2500, "holding",       ""},   // the peak gone: back
        { 800,   T,       0.500, 0.500, 0.2500, "holding",       ""},
        { 867,   T,       0.500, 0.500, 0.2500, "holding",       ""},
        { 933,   T,       0.500, 0.500, 0.2500, "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.2500, "right_armed",   ""},
        {1033,   T,       0.500, 0.500, 0.2150, "refractory",    "+right -right"},
    });
    // clang-format on
}

TEST(ClickHold, At10FpsAStepBackToASizeCreptFromIsStillTheHold) {
    // The same at 10 fps: the region creeps 4% larger in two frames and steps back 3.8% in one,
    // under the 9% a frame that is a jump there (a quick push grows that fast), over hold_rise.
    // A step back to the size it crept from is the region's too: right click.
    PointerController pointer = pressed(test::gesture_pointer());
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y      size    click            out
        { 600,   T,       0.500, 0.500, 0.2580, "holding",       ""},   // +3.2%: left, crept
        { 700,   T,       0.500, 0.500, 0.2600, "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.2500, "holding",       ""},   // -3.8%: a step
        { 900,   T,       0.500, 0.500, 0.2500, "holding",       ""},   // the peak gone: back
        {1000,   T,       0.500, 0.500, 0.2500, "holding",       ""},
        {1100,   T,       0.500, 0.500, 0.2500, "right_armed",   ""},
        {1200,   T,       0.500, 0.500, 0.2150, "refractory",    "+right -right"},
    });
    // clang-format on
}

TEST(ClickHold, APushComingBackPastTheSizeItJumpedFromIsNotHeldThere) {
    // Held at 0.250, the region jumps to 0.280 and the hand holds there; coming back, the size
    // passes 0.250 for one frame. That size was still since 0.5 s, but a return must stay 0.2 s
    // (twice hold_flicker_seconds) before it arms: the pull-back left-clicks.
    PointerController pointer = pressed(test::gesture_pointer());
    // clang-format off
    play(pointer, {
        { 600,   T,       0.500, 0.500, 0.280,  "holding",       ""},   // +12%: a jump
        { 700,   T,       0.500, 0.500, 0.280,  "holding",       ""},
        { 800,   T,       0.500, 0.500, 0.280,  "holding",       ""},
        { 900,   T,       0.500, 0.500, 0.280,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.252,  "holding",       ""},   // coming back
        {1100,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left"},
    });
    // clang-format on
}

TEST(ClickHold, ARegionThatMovesAsThePushComesBackDoesNotScroll) {
    // Right click armed, and on the way back the region changes shape: the size 17% under the
    // held size with the centroid 0.03 frame widths up, past the hold radius (0.02). Half of
    // release_drop (0.25) under the held size the push is coming back: no scroll, and the
    // pull-back right-clicks. With release_drop 0 the same frame scrolls.
    // clang-format off
    const std::vector<test::PointerRow> back = {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.230,  "rising",        ""},
        { 500,   T,       0.500, 0.500, 0.300,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.300,  "right_armed",   ""},
        {1100,   T,       0.500, 0.460, 0.250,  "right_armed",   ""},   // 0.03 up, -17%
        {1200,   T,       0.500, 0.460, 0.210,  "refractory",    "+right -right"},
    };
    // clang-format on
    PointerSettings s = test::gesture_pointer();
    s.click.release_drop = 0.25;
    PointerController pointer(s, aspect);
    play(pointer, back);
    PointerController no_drop(test::gesture_pointer(), aspect);
    std::vector<test::PointerRow> scrolled = back;
    scrolled[6].click = "scrolling";
    scrolled[6].out = "wheel 3 hires 360";
    scrolled[7].out = "";
    play(no_drop, scrolled);
}

}  // namespace
}  // namespace raypoint::core
