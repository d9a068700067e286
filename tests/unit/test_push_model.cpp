// SPDX-License-Identifier: MIT
// The push model (push_travel and push_region_jump, push_dip, the hold across a centroid jump) as
// transcripts (test_pointer_transcript.hpp): 10 fps rows in, the click state and the device command
// out. The transcripts' centroid is the row's x, y, as the smoothed position is. Settings: those of
// test_click_machine.cpp (start 5%, press 20%, release 10%, push 0.35 s, no hold, a constant
// baseline) with, in each test, the part under test on.

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

PointerSettings glitches() {
    PointerSettings s = depth();
    s.click.glitch_jump = 0.1;
    return s;
}

// push_travel 0.1 of the size, with the region's jumps left out up to 0.4 of it.
PointerSettings region_steps() {
    PointerSettings s = glitches();
    s.click.push_travel = 0.1;
    s.click.push_region_jump = 0.4;
    return s;
}

TEST(PushModel, AnApproachCarriedSidewaysIsNotAPush) {
    // push_travel 0.1: the position may move 0.1 of the size (0.02 frame widths here) while
    // the push rises. The hand comes 22% closer while moving 0.06 frame widths: an approach.
    PointerSettings settings = depth();
    settings.click.push_travel = 0.1;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.51, 0.5,  0.215,  "rising",     "rel -10 0"},
        { 500,   T,       0.53, 0.5,  0.230,  "drifting",   "rel -20 0"},  // 0.03 > 0.02
        { 600,   T,       0.56, 0.5,  0.245,  "drifting",   "rel -30 0"},  // no press
    });
    // clang-format on
    // The same push in place presses.
    PointerController still(settings, aspect);
    // clang-format off
    play(still, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.51, 0.5,  0.215,  "rising",     "rel -10 0"},
        { 500,   T,       0.515,0.5,  0.230,  "rising",     "rel -5 0"},
        { 600,   T,       0.515,0.5,  0.245,  "pressed",    "rel 15 0 +left"},  // undone
    });
    // clang-format on
}

TEST(PushModel, TheTravelIsAgainstTheTargetsOwnSize) {
    // push_travel 0.1 after a step the signal took out: the target's size is 0.27, the signal's
    // 0.2. A push that moves the position 0.025 frame widths is within 0.1 of the target's size
    // (0.027) and presses; against the signal's (0.02) it would be an approach.
    PointerSettings settings = glitches();
    settings.click.push_travel = 0.1;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.56, 0.5,  0.270,  "idle",       "rel -60 0"},  // absorbed
        { 500,   T,       0.56, 0.5,  0.270,  "idle",       ""},
        { 600,   T,       0.56, 0.5,  0.270,  "idle",       ""},
        { 700,   T,       0.585,0.5,  0.310,  "rising",     "rel -25 0"},  // +15%
        { 800,   T,       0.585,0.5,  0.340,  "pressed",    "rel 25 0 +left"},
    });
    // clang-format on
}

// The transcripts' position is the centroid itself: no smoothing between them.
const OutputSettings unsmoothed{SmoothingKind::ema, 0.0};

TEST(PushModel, TheRegionsStepIsNoTravel) {
    // push_travel 0.1 (0.02 frame widths at size 0.2), 30 fps: while the push rises, the region
    // takes in a piece of the background, +14% with the centroid 0.04 frame widths aside. The
    // depth signal takes the step out, and the travel leaves its jump out too
    // (push_region_jump: 0.04 is within 0.4 of the size): the push goes on growing where it
    // is and presses. The same move with no step is the hand carried along
    // (AnApproachCarriedSidewaysIsNotAPush).
    PointerSettings settings = region_steps();
    PointerController pointer(settings, aspect, unsmoothed);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 367,   T,       0.54, 0.5,  0.245,  "rising",     "rel -40 0"},  // absorbed
        { 400,   T,       0.545,0.5,  0.262,  "rising",     "rel -5 0"},
        { 434,   T,       0.55, 0.5,  0.280,  "pressed",    "rel 45 0 +left"},
    });
    // clang-format on
    // Counting every jump (push_region_jump 0), the push is carried off by the step, on the
    // first frame after it whose centroid did not jump.
    settings.click.push_region_jump = 0.0;
    PointerController counted(settings, aspect, unsmoothed);
    // clang-format off
    play(counted, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 367,   T,       0.54, 0.5,  0.245,  "rising",     "rel -40 0"},  // jumped: not judged
        { 400,   T,       0.545,0.5,  0.262,  "drifting",   "rel -5 0"},
    });
    // clang-format on
}

TEST(PushModel, ALeakGivenBackIsNoTravel) {
    // 10 fps: while the push rises, the region leaks into the background for one frame (size
    // 0.2 to 0.45, the centroid 0.19 frame widths down, far past push_region_jump's cap of
    // 0.072) and is back on the next. On the leak's frame the travel is not judged, since its
    // centroid jumped; the next frame gives the step back with the centroid, the jump leaves
    // the travel, and the push, now 30% up, presses where it began.
    PointerController pointer(region_steps(), aspect, unsmoothed);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.4,  0.6,  0.180,  "idle",       ""},
        { 300,   T,       0.4,  0.6,  0.180,  "idle",       ""},
        { 400,   T,       0.4,  0.6,  0.200,  "rising",     ""},           // +11%
        { 500,   T,       0.4,  0.79, 0.450,  "rising",     "rel 0 142"},  // absorbed
        { 600,   T,       0.4,  0.6,  0.234,  "pressed",    "rel 0 -142 +left"},
    });
    // clang-format on
}

TEST(PushModel, ASwipeOfStepsIsTravel) {
    // A hand that sets off on a swipe after coming closer: every frame of the swipe is a size
    // step the depth signal takes out, the centroid 0.04 frame widths on each time. Their sum
    // passes push_region_jump (0.4 of the size 0.2: 0.08) on the third: the travel counts what
    // passes it (0.04, over push_travel's 0.02) and the rise is an approach while moving.
    // Leaving all of it out, the swipe would
    // press once the centroid stops (press_hold_seconds 0.03 holds on frames without a jump).
    PointerSettings settings = region_steps();
    settings.click.press_hold_seconds = 0.03;
    PointerController pointer(settings, aspect, unsmoothed);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 367,   T,       0.5,  0.5,  0.260,  "rising",     ""},           // +30%: held
        { 400,   T,       0.54, 0.5,  0.290,  "rising",     "rel -40 0"},  // steps taken out
        { 434,   T,       0.58, 0.5,  0.260,  "rising",     "rel -40 0"},
        { 467,   T,       0.62, 0.5,  0.290,  "rising",     "rel -40 0"},  // 0.12 > 0.08
        { 500,   T,       0.62, 0.5,  0.290,  "drifting",   ""},  // judged: no jump
        { 534,   T,       0.62, 0.5,  0.290,  "drifting",   ""},
    });
    settings.click.push_region_jump = 10.0;
    PointerController unchecked(settings, aspect, unsmoothed);
    play(unchecked, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 367,   T,       0.5,  0.5,  0.260,  "rising",     ""},
        { 400,   T,       0.54, 0.5,  0.290,  "rising",     "rel -40 0"},
        { 434,   T,       0.58, 0.5,  0.260,  "rising",     "rel -40 0"},
        { 467,   T,       0.62, 0.5,  0.290,  "rising",     "rel -40 0"},
        { 500,   T,       0.62, 0.5,  0.290,  "rising",     ""},
        { 534,   T,       0.62, 0.5,  0.290,  "pressed",    "rel 120 0 +left"},
    });
    // clang-format on
}

TEST(PushModel, AFlickerPastTheCapIsStillTheRegions) {
    // The region jumps the centroid 0.095 frame widths for a frame (past push_region_jump's
    // 0.08 at size 0.2) and comes half-way back, both steps taken out. Past the cap only the
    // cap's share of the jumps is left out of the travel (0.015 counts, under push_travel's
    // 0.02), and once they are back under it all of them: the push presses. Counting all of
    // them past the cap, it drifted at the flicker.
    PointerSettings settings = region_steps();
    PointerController pointer(settings, aspect, unsmoothed);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 367,   T,       0.595,0.5,  0.262,  "rising",     "rel -95 0"},  // absorbed
        { 400,   T,       0.55, 0.5,  0.240,  "rising",     "rel 45 0"},   // absorbed
        { 434,   T,       0.55, 0.5,  0.270,  "pressed",    "rel 50 0 +left"},
    });
    // clang-format on
}

TEST(PushModel, ARiseWhoseCentroidJumpsDoesNotPress) {
    // press_hold_seconds 0.03 at 30 fps: a hand setting off on a swipe smears into a trail,
    // +25% with the centroid still, then jumps away 0.24 of its size a frame. The frames that
    // jump never hold the press. The same rise in place presses on its second frame.
    PointerSettings settings = glitches();
    settings.click.press_hold_seconds = 0.03;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.250,  "rising",     ""},           // +25%
        { 367,   T,       0.56, 0.5,  0.250,  "rising",     "rel -60 0"},  // jumps: no press
        { 400,   T,       0.62, 0.5,  0.250,  "rising",     "rel -60 0"},
    });
    PointerController still(settings, aspect);
    play(still, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 334,   T,       0.5,  0.5,  0.250,  "rising",     ""},
        { 367,   T,       0.5,  0.5,  0.250,  "pressed",    "+left"},
    });
    // clang-format on
}

TEST(PushModel, ARiseThatFallsBackIsNotAPush) {
    // push_dip 0.05: the bob of a step raises the size and drops it again; a push keeps
    // growing. Drifting until the rise is back under start_rise.
    PointerSettings settings = depth();
    settings.click.push_dip = 0.05;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.230,  "rising",     ""},   // +15%
        { 500,   T,       0.5,  0.5,  0.216,  "drifting",   ""},   // 6% under its largest
        { 600,   T,       0.5,  0.5,  0.250,  "drifting",   ""},   // +25%: no press
        { 700,   T,       0.5,  0.5,  0.205,  "idle",       ""},   // back: +2.5%
    });
    // clang-format on
}

TEST(PushModel, AQuickPushAtTenFpsPressesOnItsFirstFrameBack) {
    // press_hold_seconds 0.05 at 10 fps: the rise must be at the press on two frames. A push of
    // 0.2 s in and straight back is at the press on its last frame in and its first frame back,
    // which is also 6% under its largest: held at the press, it presses before the dip counts.
    PointerSettings settings = depth();
    settings.click.push_dip = 0.05;
    settings.click.press_hold_seconds = 0.05;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.260,  "rising",     ""},       // +30%
        { 500,   T,       0.5,  0.5,  0.244,  "pressed",    "+left"},  // +22%, 6% under 0.26
        { 600,   T,       0.5,  0.5,  0.200,  "pressed",    ""},
        { 700,   T,       0.5,  0.5,  0.200,  "refractory", "-left"},
    });
    // clang-format on
}

// With the movement's chain (Tracker, follow_movement), the reported centroid and the position
// are the chain's point, which wanders over a push's growing outline; the region's centroid
// stays where the push began. push_travel 0.1 (0.02 frame widths at size 0.2), unsmoothed: the
// chain 0.04 frame widths aside is no travel, as the region did not move; the same positions
// from the region itself are an approach carried sideways.
TEST(PushModel, TheChainsWanderIsNoTravel) {
    PointerSettings settings = depth();
    settings.click.push_travel = 0.1;
    struct Row {
        double ms, chain_x, size;
    };
    const std::vector<Row> rows = {{0, 0.0, 0.0},      {200, 0.5, 0.2},   {300, 0.5, 0.2},
                                   {400, 0.51, 0.215}, {500, 0.53, 0.23}, {600, 0.54, 0.245}};
    for (const bool followed : {true, false}) {
        SCOPED_TRACE(followed ? "followed" : "the region's own centroid");
        PointerController pointer(settings, aspect, unsmoothed);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const Row& row = rows[i];
            FrameResult frame = test::frame_of(
                {row.ms, T, row.chain_x, 0.5, i == 0 ? picked : row.size, nullptr, ""},
                static_cast<std::int64_t>(i));
            if (followed && frame.area) {
                frame.followed = true;
                frame.region_centroid = {0.5, 0.5};
            }
            pointer.update(frame);
        }
        EXPECT_EQ(to_string(pointer.click_machine().state()),
                  std::string_view(followed ? "pressed" : "drifting"));
        EXPECT_EQ(pointer.is_down(Button::left), followed);
    }
}

TEST(PushModel, ARiseHalfWayToItsTravelWaitsForTheRest) {
    // push_travel 0.1 (0.02 frame widths here), travel_hold_seconds 0.15. A hand opening from a
    // fist: its size rises 25% in 0.1 s while the position, smoothed, follows the fingers' side
    // late. Past half of push_travel at 500 ms it is not pressed yet; at 700 ms the travel is
    // past push_travel: an approach while moving. Without the hold it presses at 500 ms.
    PointerSettings settings = depth();
    settings.click.push_travel = 0.1;
    settings.click.travel_hold_seconds = 0.15;
    // clang-format off
    const std::vector<test::PointerRow> opening = {
        {   0,   T,       0.0,   0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,   0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,   0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.505, 0.5,  0.220,  "rising",     "rel -5 0"},
        { 500,   T,       0.512, 0.5,  0.250,  "rising",     "rel -7 0"},   // 0.012 > 0.01
        { 600,   T,       0.518, 0.5,  0.255,  "rising",     "rel -6 0"},   // held 0.1 s
        { 700,   T,       0.525, 0.5,  0.255,  "drifting",   "rel -7 0"},   // 0.025 > 0.02
    };
    // clang-format on
    PointerController pointer(settings, aspect);
    play(pointer, opening);
    settings.click.travel_hold_seconds = 0.0;
    PointerController at_once(settings, aspect);
    std::vector<test::PointerRow> pressed(opening.begin(), opening.begin() + 5);
    pressed[4].click = "pressed";
    pressed[4].out = "rel 5 0 +left";
    play(at_once, pressed);
}

TEST(PushModel, APushInPlaceIsNotHeldForItsTravel) {
    // The same rise with the position within half of push_travel: pressed at once.
    PointerSettings settings = depth();
    settings.click.push_travel = 0.1;
    settings.click.travel_hold_seconds = 0.15;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,   0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,   0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,   0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.505, 0.5,  0.220,  "rising",     "rel -5 0"},
        { 500,   T,       0.508, 0.5,  0.250,  "pressed",    "rel 5 0 +left"},  // 0.008
    });
    // clang-format on
}

}  // namespace
}  // namespace raypoint::core
