// SPDX-License-Identifier: MIT
// Click by dwelling (click.mode = dwell) as transcripts (test_pointer_transcript.hpp): the
// cursor held within 0.015 frame widths for 1 s clicks once (press and release in one command),
// then not again until it has moved out of that radius. 10 fps rows, 4:3 frame, clicks allowed
// after 0.2 s of tracking. The state column is the DwellState.

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
using test::Watch;

// A dead zone of 0.1 widths/s (0.01 a frame) keeps the small moves below out of the output,
// so the out column shows the clicks; 0.0304 a frame gives (0.0304 - 0.01) x 1000 = 20.4 px.
PointerSettings dwell() {
    PointerSettings s = test::linear_pointer();
    s.motion.dead_zone = 0.1;
    s.click.mode = ClickMode::dwell;
    s.dwell.seconds = 1.0;
    s.dwell.radius = 0.015;
    s.safety.min_tracking_seconds = 0.2;
    return s;
}

TEST(DwellClick, StillForASecondClicksOnce) {
    PointerController pointer(dwell(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x       y      size   state       out
        {   0,   T,       0.0,   0.0,   picked, "inactive", ""},
        { 100,   T,       0.5000, 0.500, 0.2,   "inactive", ""},
        { 200,   T,       0.5304, 0.500, 0.2,   "waiting",  "rel -20 0"},  // 20.4; anchored
        { 300,   T,       0.5608, 0.500, 0.2,   "waiting",  "rel -20 0"},  // 20.8; moved: again
        { 400,   T,       0.5650, 0.500, 0.2,   "waiting",  ""},
        { 900,   T,       0.5650, 0.505, 0.2,   "waiting",  ""},
        {1299,   T,       0.5608, 0.505, 0.2,   "waiting",  ""},           // 0.999 s
        {1300,   T,       0.5608, 0.505, 0.2,   "clicked",  "+left -left"},
        {1400,   T,       0.5608, 0.505, 0.2,   "clicked",  ""},
        {3000,   T,       0.5608, 0.505, 0.2,   "clicked",  ""},           // once only
        {3500,   T,       0.5608, 0.518, 0.2,   "clicked",  ""},           // 0.018 down = 0.0135
        {4000,   T,       0.5778, 0.500, 0.2,   "waiting",  ""},           // 0.017 across: out
        {4999,   T,       0.5778, 0.500, 0.2,   "waiting",  ""},
        {5000,   T,       0.5778, 0.500, 0.2,   "clicked",  "+left -left"},
    }, Watch::dwell);
    // clang-format on
    EXPECT_FALSE(pointer.is_down(Button::left));
}

TEST(DwellClick, NeedsTrackingAndMinTrackingSeconds) {
    PointerSettings s = dwell();
    s.safety.min_tracking_seconds = 1.5;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive", ""},
        { 100,   T,       0.5,   0.5,   0.2,    "inactive", ""},
        {1200,   T,       0.5,   0.5,   0.2,    "inactive", ""},   // still 1.1 s, tracked 1.2 s
        {1500,   T,       0.5,   0.5,   0.2,    "waiting",  ""},   // the dwell starts now
        {2000,   S,       0.0,   0.0,   0.0,    "inactive", ""},   // lost
        {2100,   T,       0.0,   0.0,   picked, "inactive", ""},
        {3600,   T,       0.5,   0.5,   0.2,    "waiting",  ""},
        {4599,   T,       0.5,   0.5,   0.2,    "waiting",  ""},
        {4600,   T,       0.5,   0.5,   0.2,    "clicked",  "+left -left"},
    }, Watch::dwell);
    // clang-format on
}

TEST(DwellClick, ReleaseAllStartsOver) {
    PointerController pointer(dwell(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,   picked, "inactive", ""},
        { 200,   T,       0.5,   0.5,   0.2,    "waiting",  ""},
        { 900,   T,       0.5,   0.5,   0.2,    "waiting",  ""},
    }, Watch::dwell);
    // clang-format on
    EXPECT_EQ(test::format(pointer.release_all()), "");  // a dwell click never stays down
    // clang-format off
    play(pointer, {
        {1000,   T,       0.5,   0.5,   0.2,    "inactive", ""},
        {1200,   T,       0.5,   0.5,   0.2,    "waiting",  ""},   // 1 s from here, not 200
        {1300,   T,       0.5,   0.5,   0.2,    "waiting",  ""},
        {2200,   T,       0.5,   0.5,   0.2,    "clicked",  "+left -left"},
    }, Watch::dwell);
    // clang-format on
}

}  // namespace
}  // namespace raypoint::core
