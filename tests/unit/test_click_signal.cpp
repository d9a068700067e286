// SPDX-License-Identifier: MIT
// The depth signal (depth_signal.hpp) and the settling after its steps (settle_seconds) as
// transcripts (test_pointer_transcript.hpp): 10 fps rows in, the click state and the device
// command out. The transcripts' centroid is the row's x, y, as the smoothed position is.
// Settings: those of test_click_machine.cpp (start 5%, press 20%, release 10%, push 0.35 s, no
// hold, a constant baseline) with, in each test, the part under test on.

#include <gtest/gtest.h>

#include "raypoint/core/depth_signal.hpp"
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

TEST(DepthSignal, AStepWithACentroidJumpThatStaysIsNotAPush) {
    // The region takes in something beside the target: +35% and the centroid 0.3 of the
    // size away, and it stays so. Without the signal it would press; with it the level is
    // the new baseline, and a push from there presses.
    PointerController pointer(glitches(), aspect);
    // clang-format off
    play(pointer, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.56, 0.5,  0.270,  "idle",       "rel -60 0"},  // absorbed
        { 500,   T,       0.56, 0.5,  0.270,  "idle",       ""},           // and it stays
        { 600,   T,       0.56, 0.5,  0.270,  "idle",       ""},
        { 700,   T,       0.56, 0.5,  0.300,  "rising",     ""},           // +11%: a push
        { 800,   T,       0.56, 0.5,  0.330,  "pressed",    "+left"},      // +22%
    });
    // clang-format on
}

TEST(DepthSignal, AMergeStillGrowingAfterItsStepRaisesTheBaseline) {
    // settle_seconds 0.1: the region takes in a ball passing, +35% with the centroid 0.3 of the
    // size away (absorbed), and takes in more on the next frame, +11% with the centroid still.
    // That growth raises the baseline instead of starting a push; a push after the 0.1 s
    // presses. Without settle_seconds the merge's growth is a push and presses at 700 ms.
    PointerSettings settings = glitches();
    settings.click.settle_seconds = 0.1;
    PointerController settling(settings, aspect);
    // clang-format off
    play(settling, {
        //  ms   tracker  x     y     size    click         out
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.56, 0.5,  0.270,  "idle",       "rel -60 0"},  // absorbed
        { 500,   T,       0.56, 0.5,  0.300,  "idle",       ""},           // the baseline +11%
        { 600,   T,       0.56, 0.5,  0.300,  "idle",       ""},
        { 700,   T,       0.56, 0.5,  0.330,  "rising",     ""},           // +10%: a push
        { 800,   T,       0.56, 0.5,  0.370,  "pressed",    "+left"},      // +23%
    });
    settings.click.settle_seconds = 0.0;
    PointerController not_settling(settings, aspect);
    play(not_settling, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.56, 0.5,  0.270,  "idle",       "rel -60 0"},
        { 500,   T,       0.56, 0.5,  0.300,  "rising",     ""},           // +11%
        { 600,   T,       0.56, 0.5,  0.300,  "rising",     ""},
        { 700,   T,       0.56, 0.5,  0.330,  "pressed",    "+left"},      // +22%
    });
    // clang-format on
}

TEST(DepthSignal, TheStepLimitGrowsWithTheTimeBetweenFrames) {
    // +15% with the centroid 0.15 of the size away: at 30 fps a step over glitch_step (8%) the
    // signal absorbs; at 10 fps under its 24%, a push's own frame, which rises.
    PointerController at30(glitches(), aspect);
    // clang-format off
    play(at30, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 233,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 267,   T,       0.47, 0.5,  0.230,  "idle",       "rel 30 0"},   // absorbed
    });
    PointerController at10(glitches(), aspect);
    play(at10, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.47, 0.5,  0.230,  "rising",     "rel 30 0"},   // +15%
    });
    // clang-format on
}

TEST(DepthSignal, AOneFrameGlitchThatComesBackIsNotAPush) {
    // 0.035 -> 0.10 -> 0.035 of the frame's area has been seen: sqrt(area) +70% for one frame.
    PointerController pointer(glitches(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.44, 0.5,  0.340,  "idle",       "rel 60 0"},   // absorbed
        { 500,   T,       0.5,  0.5,  0.200,  "idle",       "rel -60 0"},  // back: given back
        { 600,   T,       0.5,  0.5,  0.200,  "idle",       ""},
    });
    // clang-format on
}

TEST(DepthSignal, APushWhoseCentroidBlipsForOneFramePresses) {
    // At 10 fps a quick push is one frame, and the frame may blur: +35% with the centroid
    // 0.3 of the size away, back in place the next frame with the size still up. The step is
    // given back on that frame, which presses.
    PointerController pointer(glitches(), aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.56, 0.270,  "idle",       "rel 0 45"},  // absorbed
        { 500,   T,       0.5,  0.5,  0.280,  "pressed",    "+left"},     // given back: +40%
    });
    // clang-format on
}

TEST(DepthSignal, AStepGivenBackCountsFromTheFrameItCameOn) {
    // push_seconds 0.25: the push began after 300 ms; its big step came at 500 ms with a
    // centroid blip and is given back at 600 ms, 0.3 s in. It came 0.2 s in: a press.
    PointerSettings settings = glitches();
    settings.click.push_seconds = 0.25;
    PointerController pointer(settings, aspect);
    // clang-format off
    play(pointer, {
        {   0,   T,       0.0,  0.0,  picked, "inactive",   ""},
        { 200,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 300,   T,       0.5,  0.5,  0.200,  "idle",       ""},
        { 400,   T,       0.5,  0.5,  0.215,  "rising",     ""},
        { 500,   T,       0.5,  0.56, 0.290,  "rising",     "rel 0 45"},        // held back
        { 600,   T,       0.5,  0.5,  0.300,  "pressed",    "rel 0 -45 +left"}, // given back
    });
    // clang-format on
}

TEST(DepthSignal, StepsWithoutACentroidJumpAndSmallStepsAreKept) {
    DepthSignal signal(glitches().click);
    const cv::Point2d here(0.5, 0.4);
    EXPECT_DOUBLE_EQ(*signal.update(0.20, here), 0.20);
    EXPECT_DOUBLE_EQ(*signal.update(0.27, here + cv::Point2d(0.005, 0)), 0.27);  // a push
    EXPECT_FALSE(signal.absorbed());
    // 5%, under glitch_step, with a jump of 0.3 of the size: the target's own motion.
    EXPECT_DOUBLE_EQ(*signal.update(0.2835, here + cv::Point2d(0.09, 0)), 0.2835);
    EXPECT_FALSE(signal.absorbed());
    // No target: nothing, and a fresh start.
    EXPECT_FALSE(signal.update(std::nullopt, here).has_value());
    EXPECT_DOUBLE_EQ(*signal.update(0.4, here), 0.4);
}

TEST(DepthSignal, AStepIsGivenBackOnlyWhenTheCentroidComesMostOfTheWayBack) {
    // glitch_return 0.7: the region takes in a piece, +35% with the centroid 0.15 of the size
    // away; the next frame the centroid comes back half of that, the piece still in: the step
    // stays out. Back 0.8 of the way, it was the target's own and is given back.
    ClickSettings click = glitches().click;
    click.glitch_return = 0.7;
    const cv::Point2d here(0.5, 0.4);
    DepthSignal settling(click);
    EXPECT_DOUBLE_EQ(*settling.update(0.20, here), 0.20);
    EXPECT_NEAR(*settling.update(0.27, here + cv::Point2d(0.03, 0)), 0.20, 1e-12);
    EXPECT_TRUE(settling.absorbed());
    EXPECT_NEAR(*settling.update(0.27, here + cv::Point2d(0.015, 0)), 0.20, 1e-12);
    EXPECT_FALSE(settling.given_back());
    DepthSignal blurred(click);
    EXPECT_DOUBLE_EQ(*blurred.update(0.20, here), 0.20);
    EXPECT_NEAR(*blurred.update(0.27, here + cv::Point2d(0.03, 0)), 0.20, 1e-12);
    EXPECT_NEAR(*blurred.update(0.27, here + cv::Point2d(0.006, 0)), 0.27, 1e-12);
    EXPECT_TRUE(blurred.given_back());
}

TEST(DepthSignal, ALeakThatClosesFramesLaterIsTakenOutAsItsOpeningWas) {
    // A push under way takes in a strip of the background (+14%, the centroid 0.14 of the
    // size away), keeps it a frame, then drops it (-6%) with the centroid back. Within
    // glitch_return_seconds the drop is taken out as the strip's arrival was and the push's
    // level stands; with 0 only the next frame could give the step back, and the drop is a
    // 6% dip, over push_dip.
    const cv::Point2d here(0.5, 0.4);
    const cv::Point2d beside = here + cv::Point2d(0.03, 0);
    const cv::Point2d back = here + cv::Point2d(0.002, 0);
    constexpr Timestamp frame = 33'333;
    for (const double window : {0.0, 0.1}) {
        ClickSettings click = glitches().click;
        click.glitch_return_seconds = window;
        DepthSignal signal(click);
        signal.update(0.20, here, 0);
        signal.update(0.21, here, frame);
        EXPECT_NEAR(*signal.update(0.24, beside, 2 * frame), 0.21, 1e-12);
        EXPECT_TRUE(signal.absorbed());
        EXPECT_NEAR(*signal.update(0.25, beside, 3 * frame), 0.21875, 1e-12);
        EXPECT_FALSE(signal.given_back());
        const double level = *signal.update(0.235, back, 4 * frame);
        if (window > 0.0) {
            EXPECT_NEAR(level, 0.21875, 1e-12);
            EXPECT_TRUE(signal.absorbed());
        } else {
            EXPECT_NEAR(level, 0.235 * 0.21 / 0.24, 1e-12);
            EXPECT_FALSE(signal.absorbed());
        }
    }
}

TEST(DepthSignal, TheEndOfALeakTheFrameIntervalLetThroughIsNotTakenOut) {
    // 10 fps: a held push (0.26) leaks into the background for one frame, +19% with the
    // centroid 0.19 of the size away: under the 24% a 10 fps frame allows, so it stays in.
    // The next frame the centroid is back and the size is down 29% (the leak gone, the hand
    // coming back): the leak's end. Taken out, the signal would keep the leak's 0.31 while the
    // hand pulls back, and a press would never come up.
    const cv::Point2d here(0.5, 0.4);
    const cv::Point2d leaked = here + cv::Point2d(0, 0.05);
    constexpr Timestamp frame = 100'000;
    DepthSignal signal(glitches().click);
    EXPECT_DOUBLE_EQ(*signal.update(0.26, here, 0), 0.26);
    EXPECT_DOUBLE_EQ(*signal.update(0.31, leaked, frame), 0.31);
    EXPECT_FALSE(signal.absorbed());
    EXPECT_TRUE(signal.stepped());  // past glitch_step and glitch_jump between two frames
    EXPECT_DOUBLE_EQ(*signal.update(0.22, here, 2 * frame), 0.22);
    EXPECT_FALSE(signal.absorbed());
    // The leak's end coming 1/30 s later (the camera's rate back up): the allowance that let
    // the leak through was its own frame's, so the end is still kept.
    DepthSignal faster(glitches().click);
    faster.update(0.26, here, 0);
    faster.update(0.31, leaked, frame);
    EXPECT_DOUBLE_EQ(*faster.update(0.22, here, frame + 33'333), 0.22);
    EXPECT_FALSE(faster.absorbed());
    // The same drop with the centroid not back is a piece leaving: taken out.
    DepthSignal elsewhere(glitches().click);
    elsewhere.update(0.26, here, 0);
    elsewhere.update(0.31, leaked, frame);
    EXPECT_NEAR(*elsewhere.update(0.22, leaked + cv::Point2d(0.05, 0), 2 * frame), 0.31, 1e-12);
    EXPECT_TRUE(elsewhere.absorbed());
    EXPECT_TRUE(elsewhere.stepped());
    // A step under glitch_step between the frames is no region step, whatever the centroid.
    EXPECT_NEAR(*elsewhere.update(0.23, here, 3 * frame), 0.23 * 0.31 / 0.22, 1e-12);
    EXPECT_FALSE(elsewhere.stepped());
}

TEST(DepthSignal, TheReturnOfAPieceLostForOneFrameIsNotTakenOut) {
    // 30 fps: the region loses a piece for one frame, -9.8% with the centroid 0.093 of the
    // size away (under glitch_jump, so it stays in), then the third frame below. Its step from
    // the lost frame is over glitch_step, and its centroid's jump over glitch_jump of the
    // smaller size in every case.
    const cv::Point2d here(0.5, 0.4);
    const cv::Point2d lost = here + cv::Point2d(0, 0.025);
    constexpr Timestamp frame = 33'333;
    struct Third {
        const char* what;
        double size;
        cv::Point2d centroid;
        bool taken_out;
    };
    const Third thirds[] = {
        // Taken out, the return would hold the signal 10% under the target for good, and a
        // push from there would fall short of the press.
        {"the piece back", 0.27, here, false},
        // A region flickering between two shapes comes back to the size, not always to the
        // same centroid: the size back within glitch_step is the end too.
        {"the size back, the centroid not", 0.266, here + cv::Point2d(0.012, 0), false},
        {"neither back: something else taken in", 0.30, here + cv::Point2d(0.012, 0), true},
        {"on the way it went: another piece lost", 0.20, lost + cv::Point2d(0, 0.025), true},
    };
    for (const Third& third : thirds) {
        SCOPED_TRACE(third.what);
        DepthSignal signal(glitches().click);
        EXPECT_DOUBLE_EQ(*signal.update(0.268, here, 0), 0.268);
        EXPECT_DOUBLE_EQ(*signal.update(0.2418, lost, frame), 0.2418);
        EXPECT_FALSE(signal.absorbed());
        const double level = *signal.update(third.size, third.centroid, 2 * frame);
        EXPECT_NEAR(level, third.taken_out ? 0.2418 : third.size, 1e-12);
        EXPECT_EQ(signal.absorbed(), third.taken_out);
    }
}

TEST(DepthSignal, ARegionThatKeepsItsPieceWithTheCentroidBackIsNotTakenOutAgain) {
    // The same strip, but the region grows on with the centroid back: the piece is still in
    // (a region can bring its centroid back and keep it), and the push goes on from the level
    // with the strip taken out.
    ClickSettings click = glitches().click;
    click.glitch_return_seconds = 0.1;
    const cv::Point2d here(0.5, 0.4);
    constexpr Timestamp frame = 33'333;
    DepthSignal signal(click);
    signal.update(0.20, here, 0);
    signal.update(0.21, here, frame);
    signal.update(0.24, here + cv::Point2d(0.03, 0), 2 * frame);
    signal.update(0.25, here + cv::Point2d(0.03, 0), 3 * frame);
    EXPECT_NEAR(*signal.update(0.26, here + cv::Point2d(0.002, 0), 4 * frame), 0.26 * 0.21 / 0.24,
                1e-12);
    EXPECT_FALSE(signal.absorbed());
    EXPECT_FALSE(signal.given_back());
}

TEST(DepthSignal, ACentroidJumpCountsPerThirtiethOfASecond) {
    // glitch_jump 0.1: 0.03 frame widths is 0.15 of a size of 0.2, a jump 1/30 s after the
    // last frame; 0.1 s after it, three frames' worth of a push's own drift, it is not.
    const cv::Point2d here(0.5, 0.4);
    DepthSignal signal(glitches().click);
    signal.update(0.20, here, 0);
    signal.update(0.20, here + cv::Point2d(0.03, 0), 33'333);
    EXPECT_TRUE(signal.jumped());
    EXPECT_FALSE(signal.absorbed());  // the size kept still
    signal.update(0.20, here + cv::Point2d(0.06, 0), 133'333);
    EXPECT_FALSE(signal.jumped());
}

TEST(DepthSignal, AStepFasterThanAnyPushIsTakenOutWhereverTheCentroid) {
    // glitch_leap 0.3 per 1/30 s: at 60 fps a step of +30% with the centroid still (0.025 of
    // the size, under glitch_jump) is the region changing: a push of 40% closer in 0.15 s
    // steps at most 19% per 1/30 s. A step of +8% there is the target's own; at 10 fps the
    // limit is 90% and +30% is one frame of a quick push.
    ClickSettings click = glitches().click;
    click.glitch_leap = 0.3;
    const cv::Point2d here(0.5, 0.4);
    const cv::Point2d still = here + cv::Point2d(0.005, 0);
    DepthSignal fast(click);
    fast.update(0.20, here, 0);
    EXPECT_NEAR(*fast.update(0.26, still, 16'667), 0.20, 1e-12);
    EXPECT_TRUE(fast.absorbed());
    DepthSignal growing(click);
    growing.update(0.20, here, 0);
    EXPECT_DOUBLE_EQ(*growing.update(0.216, still, 16'667), 0.216);
    EXPECT_FALSE(growing.absorbed());
    DepthSignal slow(click);
    slow.update(0.20, here, 0);
    EXPECT_DOUBLE_EQ(*slow.update(0.26, still, 100'000), 0.26);
    EXPECT_FALSE(slow.absorbed());
    click.glitch_jump = 0.0;  // the leap alone
    DepthSignal alone(click);
    alone.update(0.20, here, 0);
    EXPECT_NEAR(*alone.update(0.26, still, 16'667), 0.20, 1e-12);
    click.glitch_leap = 0.0;
    DepthSignal off(click);
    off.update(0.20, here, 0);
    EXPECT_DOUBLE_EQ(*off.update(0.26, still, 16'667), 0.26);
}

TEST(DepthSignal, AStepOnAFrameWhoseLightJumpedIsTakenOut) {
    // glitch_light 0.1: +9% (over glitch_step's 8%) with the centroid still, on a frame whose
    // light changed by 25% (a camera's gain jump), is the outline moving with the light; the
    // same step under still light, or light changed by 5% (flicker), is the target's own.
    ClickSettings click = glitches().click;
    click.glitch_light = 0.1;
    const cv::Point2d here(0.5, 0.4);
    for (const auto& [light, absorbed] : {std::pair{0.25, true}, {0.0, false}, {0.05, false}}) {
        DepthSignal signal(click);
        signal.update(0.20, here, 0);
        signal.update(0.218, here, 33'333, light);
        EXPECT_EQ(signal.absorbed(), absorbed) << "light changed by " << light;
    }
}

TEST(DepthSignal, ThePointerPassesTheFramesLightChangeOn) {
    // The frame's light_change reaches the depth signal: a 30 fps rise of 12% a frame for three
    // frames, the first with the light 25% up, presses only from the second's growth on.
    PointerSettings settings = glitches();
    settings.click.glitch_light = 0.1;
    const auto first_press = [&](double light) {
        PointerController pointer(settings, aspect);
        double size = 0.2;
        for (int i = 0; i < 20; ++i) {
            if (i >= 15 && i < 18) size *= 1.12;
            core::FrameResult frame =
                test::frame_of({i * 100.0 / 3.0, T, 0.5, 0.5, size, nullptr, ""}, i);
            if (i == 15) frame.light_change = light;
            if (pointer.update(frame).button_changes().size() > 0) return i;
        }
        return -1;
    };
    EXPECT_EQ(first_press(0.0), 16);   // +25%: over press_rise (20%)
    EXPECT_EQ(first_press(0.25), 17);  // +12% and +25% from the absorbed step's level
}

TEST(DepthSignal, OffPassesTheScaleThrough) {
    DepthSignal signal(depth().click);  // glitch_jump 0
    EXPECT_DOUBLE_EQ(*signal.update(0.20, {0.5, 0.4}), 0.20);
    EXPECT_DOUBLE_EQ(*signal.update(0.34, {0.3, 0.4}), 0.34);
    EXPECT_FALSE(signal.absorbed());
}

}  // namespace
}  // namespace raypoint::core
