// SPDX-License-Identifier: MIT
// Double click by depth as transcripts (test_pointer_transcript.hpp): 10 fps rows in, the click
// state and the device command out. Settings: test::gesture_pointer() (double click within
// 0.6 s), most with right click and scroll off.

#include <gtest/gtest.h>

#include "raypoint/core/pointer_controller.hpp"
#include "test_pointer_transcript.hpp"

namespace raypoint::core {
namespace {

using test::aspect;
using test::picked;
using test::play;
using test::T;

PointerSettings gestures() {
    return test::gesture_pointer();
}

PointerSettings double_only() {
    PointerSettings s = gestures();
    s.click.right_seconds = 0.0;
    s.click.scroll_gain = 0.0;
    return s;
}

TEST(ClickGestures, TwoQuickPushesDoubleClick) {
    // The second push begins 0.4 s after the first click's release: its press comes after a
    // whole click, so the desktop sees two clicks within its double-click time.
    PointerController pointer(double_only(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},
        { 500,   T,       0.500, 0.500, 0.215,  "refractory",    "-left"},
        { 600,   T,       0.500, 0.500, 0.200,  "refractory",    ""},
        { 800,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 900,   T,       0.500, 0.500, 0.200,  "idle",          ""},   // the push began here
        {1000,   T,       0.500, 0.500, 0.250,  "pressed",       "+left -left +left"},
        {1100,   T,       0.500, 0.500, 0.215,  "refractory",    "-left"},
        {1300,   T,       0.500, 0.500, 0.200,  "refractory",    ""},
        {1400,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        {1500,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},  // a third: single
    });
    // clang-format on
}

TEST(ClickGestures, TwoPushesFurtherApartAreTwoClicks) {
    PointerController pointer(double_only(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},
        { 500,   T,       0.500, 0.500, 0.215,  "refractory",    "-left"},
        { 800,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        {1200,   T,       0.500, 0.500, 0.200,  "idle",          ""},   // 0.7 s after
        {1300,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},
    });
    // clang-format on
}

TEST(ClickGestures, ADragIsNotTheFirstClickOfADouble) {
    PointerController pointer(double_only(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},
        {1200,   T,       0.500, 0.500, 0.250,  "dragging",      ""},
        {1300,   T,       0.500, 0.500, 0.215,  "refractory",    "-left"},
        {1600,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        {1700,   T,       0.500, 0.500, 0.250,  "pressed",       "+left"},
    });
    // clang-format on
}

TEST(ClickGestures, APullBackTakenOutDoesNotHoldOffTheSecondPushOfADouble) {
    // The first click's pull-back ends with a step the depth signal takes out (-27%, the
    // centroid 0.13 of the size away), and the signal stays at 0.225, 12.5% over the baseline.
    // The target's own size is back where the push began: the refractory time ends at 0.3 s
    // and the baseline starts again from the signal, so the second push double-clicks.
    PointerSettings s = double_only();
    s.click.glitch_jump = 0.1;
    s.click.release_drop = 0.25;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.260,  "pressed",       "+left"},
        { 500,   T,       0.500, 0.500, 0.225,  "pressed",       ""},
        { 600,   T,       0.530, 0.500, 0.165,  "refractory",    "rel -30 0 -left"},
        { 700,   T,       0.530, 0.500, 0.165,  "refractory",    ""},
        { 900,   T,       0.530, 0.500, 0.165,  "idle",          ""},
        {1000,   T,       0.530, 0.500, 0.215,  "pressed",       "+left -left +left"},
    });
    // clang-format on
}

TEST(ClickGestures, DoubleClickWithRightClickOnComesAtTheSecondPullBack) {
    PointerController pointer(gestures(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive",      ""},
        { 200,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 300,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 400,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        { 500,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left"},
        { 800,   T,       0.500, 0.500, 0.200,  "idle",          ""},
        { 900,   T,       0.500, 0.500, 0.250,  "holding",       ""},
        {1000,   T,       0.500, 0.500, 0.215,  "refractory",    "+left -left +left -left"},
    });
    // clang-format on
}

}  // namespace
}  // namespace raypoint::core
