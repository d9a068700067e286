// SPDX-License-Identifier: MIT
// Pointer motion as transcripts (test_pointer_transcript.hpp): tracker results in, device motion
// out. 10 fps rows, a 4:3 frame (a y fraction is 0.75 frame widths), clicks off. Distances are
// in frame widths: x fractions are widths already, y fractions times 0.75.

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

// Relative, 1000 px a frame width, no dead zone, no acceleration, no clicks.
PointerSettings plain() {
    PointerSettings s = test::linear_pointer();
    s.click.mode = ClickMode::off;
    return s;
}

TEST(PointerMotion, RelativeGainMirrorAndNoJumpOnANewTarget) {
    PointerController pointer(plain(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x       y       sqrt(area) click  out
        {   0,   S,       0.0,    0.0,    0.0,    nullptr, ""},
        { 100,   T,       0.0,    0.0,    picked, nullptr, ""},          // picked: no position
        { 200,   T,       0.50,   0.50,   0.2,    nullptr, ""},          // the reference
        { 300,   T,       0.49,   0.50,   0.2,    nullptr, "rel 10 0"},  // camera left = user right
        { 400,   T,       0.49,   0.5075, 0.2,    nullptr, "rel 0 5"},   // 0.0075 x 750 = 5.625
        { 500,   T,       0.49,   0.5150, 0.2,    nullptr, "rel 0 6"},   // 5.625 + 0.625 = 6.25
        { 600,   T,       0.50,   0.5150, 0.2,    nullptr, "rel -10 0"},
        { 700,   S,       0.0,    0.0,    0.0,    nullptr, ""},          // lost: nothing moves
        { 800,   T,       0.0,    0.0,    picked, nullptr, ""},
        { 900,   T,       0.20,   0.20,   0.2,    nullptr, ""},          // elsewhere: no jump
        {1000,   T,       0.19,   0.20,   0.2,    nullptr, "rel 10 0"},
    });
    // clang-format on
}

TEST(PointerMotion, UnmirroredFollowsTheCamera) {
    PointerSettings s = plain();
    s.motion.mirror = false;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.50,   0.50,   0.2,    nullptr, ""},
        { 100,   T,       0.49,   0.50,   0.2,    nullptr, "rel -10 0"},
    });
    // clang-format on
}

TEST(PointerMotion, SlowMotionKeepsItsSubPixelRemainders) {
    // 0.0035 widths a frame at 100 px a width: 0.35 px a frame, never a whole pixel at once.
    // Truncated each frame it would never move; carried over it moves 1 px in 3 frames.
    PointerSettings s = plain();
    s.motion.gain = 100.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x        y     sqrt(area) click  out      wanted
        {   0,   T,       0.5000,  0.5,  0.2,    nullptr, ""},
        { 100,   T,       0.4965,  0.5,  0.2,    nullptr, ""},        // 0.35
        { 200,   T,       0.4930,  0.5,  0.2,    nullptr, ""},        // 0.70
        { 300,   T,       0.4895,  0.5,  0.2,    nullptr, "rel 1 0"}, // 1.05
        { 400,   T,       0.4860,  0.5,  0.2,    nullptr, ""},        // 0.40
        { 500,   T,       0.4825,  0.5,  0.2,    nullptr, ""},        // 0.75
        { 600,   T,       0.4790,  0.5,  0.2,    nullptr, "rel 1 0"}, // 1.10
        { 700,   T,       0.4825,  0.5,  0.2,    nullptr, ""},        // back: -0.25
        { 800,   T,       0.4860,  0.5,  0.2,    nullptr, ""},        // -0.60
        { 900,   T,       0.4895,  0.5,  0.2,    nullptr, ""},        // -0.95
        {1000,   T,       0.4930,  0.5,  0.2,    nullptr, "rel -1 0"},// -1.30
    });
    // clang-format on
}

TEST(PointerMotion, DeadZoneSwallowsJitterAndShrinksMotion) {
    // Dead zone 0.045 widths/s = 0.0045 widths a frame at 10 fps: jitter of 0.004 a frame moves
    // nothing; a move of 0.0213 a frame gives (0.0213 - 0.0045) x 1000 = 16.8 px.
    PointerSettings s = plain();
    s.motion.dead_zone = 0.045;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.500,   0.5,    0.2,    nullptr, ""},
        { 100,   T,       0.504,   0.5,    0.2,    nullptr, ""},
        { 200,   T,       0.500,   0.5,    0.2,    nullptr, ""},
        { 300,   T,       0.500,   0.5053, 0.2,    nullptr, ""},           // 0.0053 x 0.75 = 0.004
        { 400,   T,       0.5213,  0.5053, 0.2,    nullptr, "rel -16 0"},  // 16.8
        { 500,   T,       0.5426,  0.5053, 0.2,    nullptr, "rel -17 0"},  // 16.8 + 0.8 = 17.6
    });
    // clang-format on
}

TEST(PointerMotion, AccelerationGrowsWithSpeed) {
    // Gain 100 x (1 + 2 x speed in widths/s): 0.01 a frame (0.1/s) x 1.2; 0.05 (0.5/s) x 2;
    // 0.1 (1/s) x 3. Five times the distance gives 8.3 times the pixels, ten times 25.
    PointerSettings s = plain();
    s.motion.gain = 100.0;
    s.motion.acceleration = 2.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x       y     sqrt(area) click  out          wanted
        {   0,   T,       0.50,   0.5,  0.2,    nullptr, ""},
        { 100,   T,       0.49,   0.5,  0.2,    nullptr, "rel 1 0"},   // 1.2
        { 200,   T,       0.48,   0.5,  0.2,    nullptr, "rel 1 0"},   // 1.2 + 0.2
        { 300,   T,       0.43,   0.5,  0.2,    nullptr, "rel 10 0"},  // 10 + 0.4
        { 400,   T,       0.33,   0.5,  0.2,    nullptr, "rel 30 0"},  // 30 + 0.4
    });
    // clang-format on
}

TEST(PointerMotion, AbsoluteMapsTheActiveRegionMirrored) {
    PointerSettings s = plain();
    s.motion.mode = PointerMode::absolute;
    s.motion.absolute_max = 1000;
    s.motion.active_left = 0.1;
    s.motion.active_right = 0.9;
    s.motion.active_top = 0.1;
    s.motion.active_bottom = 0.9;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x      y     sqrt(area) click  out
        {   0,   S,       0.0,   0.0,  0.0,    nullptr, ""},
        { 100,   T,       0.0,   0.0,  picked, nullptr, ""},
        { 200,   T,       0.50,  0.50, 0.2,    nullptr, "abs 500 500"},    // at once: no reference
        { 300,   T,       0.30,  0.70, 0.2,    nullptr, "abs 750 750"},    // mirrored 0.7 -> 0.75
        { 400,   T,       0.90,  0.10, 0.2,    nullptr, "abs 0 0"},        // the region's corner
        { 500,   T,       0.97,  0.03, 0.2,    nullptr, "abs 0 0"},        // outside: clamped
        { 600,   T,       0.05,  0.95, 0.2,    nullptr, "abs 1000 1000"},
        { 700,   S,       0.0,   0.0,  0.0,    nullptr, ""},               // lost: stays put
    });
    // clang-format on
}

TEST(PointerMotion, AbsoluteDefaultRangeUnmirrored) {
    PointerSettings s = plain();
    s.motion.mode = PointerMode::absolute;
    s.motion.mirror = false;
    s.motion.active_left = 0.0;
    s.motion.active_right = 1.0;
    s.motion.active_top = 0.0;
    s.motion.active_bottom = 1.0;
    PointerController pointer(s, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.50,  0.50, 0.2,    nullptr, "abs 32768 32768"},  // 32767.5 rounded
        { 100,   T,       0.25,  1.00, 0.2,    nullptr, "abs 16384 65535"},
    });
    // clang-format on
}

TEST(PointerMotion, RepeatedTimestampMovesNothing) {
    PointerController pointer(plain(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.50,  0.50, 0.2,    nullptr, ""},
        {   0,   T,       0.40,  0.50, 0.2,    nullptr, ""},
        { 100,   T,       0.40,  0.50, 0.2,    nullptr, "rel 100 0"},  // from the last reference
    });
    // clang-format on
}

// The per-frame path cannot allocate: nothing in the pointer owns memory (no container, no
// pointer), which trivially copyable types guarantee, and update() builds none.
static_assert(std::is_trivially_copyable_v<PointerController>);
static_assert(std::is_trivially_copyable_v<PointerCommand>);

}  // namespace
}  // namespace raypoint::core
