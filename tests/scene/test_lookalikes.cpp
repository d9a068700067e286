// SPDX-License-Identifier: MIT
// The renderer's skin lookalikes: a sleeve behind the hand, a person behind it, a skin-coloured
// wall and a wooden desk; and a ball passing behind the hand. The truth stays the hand's alone,
// exactly.

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/scene/presets.hpp"
#include "raypoint/scene/renderer.hpp"
#include "renderer_testing.hpp"

namespace {

using namespace raypoint::scene;
using raypoint::scene::render_testing::still;

// The sleeve is drawn from the wrist out of the frame's bottom, not in the truth: the mask is the
// hand's with or without it, and the picture differs only outside the mask, below the hand.
TEST(SceneRenderer, SleeveIsDrawnBelowTheHandAndIsNotTheTruth) {
    SceneSpec bare = still(Target::hand, 0.9, 0.5, 0.4);
    bare.target_colour = Colour{128, 160, 214};
    SceneSpec sleeved = bare;
    sleeved.sleeve_colour = Colour{20, 20, 200};  // red, to find it
    const RenderedFrame a = Renderer(bare).render(0);
    const RenderedFrame b = Renderer(sleeved).render(0);
    EXPECT_EQ(cv::norm(a.mask, b.mask, cv::NORM_INF), 0.0);
    EXPECT_EQ(a.truth.cx, b.truth.cx);
    EXPECT_EQ(a.truth.area, b.truth.area);
    cv::Mat changed;
    cv::absdiff(a.bgr, b.bgr, changed);
    cv::cvtColor(changed, changed, cv::COLOR_BGR2GRAY);
    changed = changed > 30;
    // Inside the hand (but its anti-aliased outline, which blends what is behind it) nothing
    // changed.
    cv::Mat inside;
    cv::erode(b.mask, inside, cv::Mat());
    EXPECT_EQ(cv::countNonZero(changed & inside), 0);
    const cv::Rect box = cv::boundingRect(changed);
    const cv::Rect hand = cv::boundingRect(b.mask);
    EXPECT_EQ(box.br().y, bare.height);  // leaves the frame at the bottom
    EXPECT_GT(box.y, hand.y + hand.height / 2);
    EXPECT_LT(std::abs((box.x + box.width / 2) - (hand.x + hand.width / 2)), hand.width / 2);
    // About the wrist's width, a little more (a cuff).
    EXPECT_GT(box.width, hand.width / 5);
    EXPECT_LT(box.width, hand.width * 2 / 3);
}

// The person moves (breath, head, sway) but is background: with no target the truth is absent
// and the frames still differ around the person.
TEST(SceneRenderer, PersonMovesAndIsNotTheTruth) {
    SceneSpec s = preset("person");
    s.empty_seconds = 10;  // no hand
    s.noise_sigma = 0;
    s.seconds = 3;
    const Renderer r(s);
    const RenderedFrame first = r.render(0);
    const RenderedFrame later = r.render(45);
    EXPECT_FALSE(first.truth.present);
    EXPECT_FALSE(later.truth.present);
    EXPECT_EQ(cv::countNonZero(later.mask), 0);
    cv::Mat changed;
    cv::absdiff(first.bgr, later.bgr, changed);
    cv::cvtColor(changed, changed, cv::COLOR_BGR2GRAY);
    EXPECT_GT(cv::countNonZero(changed > 20), 200);
}

// The passing ball crosses behind the hand from the right to the left, is drawn behind it (the
// hand's inside does not change) and is never the truth: the mask is the hand's with or
// without it.
TEST(SceneRenderer, PasserCrossesBehindTheHandAndIsNotTheTruth) {
    SceneSpec bare = still(Target::hand, 0.9, 0.5, 0.5);
    bare.target_colour = Colour{128, 160, 214};
    bare.seconds = 2;
    SceneSpec passing = bare;
    passing.passes = {0.0};
    passing.pass_seconds = 1.0;
    passing.pass_colour = Colour{20, 20, 200};  // red, to find it
    const Renderer with(passing);
    const Renderer without(bare);
    const auto changed_box = [&](int index, const RenderedFrame& a) {
        const RenderedFrame b = with.render(index);
        EXPECT_EQ(cv::norm(a.mask, b.mask, cv::NORM_INF), 0.0);
        cv::Mat changed;
        cv::absdiff(a.bgr, b.bgr, changed);
        cv::cvtColor(changed, changed, cv::COLOR_BGR2GRAY);
        cv::Mat inside;
        cv::erode(b.mask, inside, cv::Mat(), {-1, -1}, 2);
        EXPECT_EQ(cv::countNonZero((changed > 30) & inside), 0) << "frame " << index;
        return cv::boundingRect(changed > 30);
    };
    // A quarter of the way (frame 8 of 30 a second): right of the middle; three quarters: left.
    const cv::Rect early = changed_box(8, without.render(8));
    const cv::Rect late = changed_box(22, without.render(22));
    const int middle = bare.width / 2;
    EXPECT_GT(early.x + early.width / 2, middle);
    EXPECT_LT(late.x + late.width / 2, middle);
    // A ball a quarter of the frame's height (the default pass_size) across, at mid-height.
    EXPECT_NEAR(early.height, bare.height / 4, bare.height / 20);
    EXPECT_NEAR(early.y + early.height / 2, bare.height / 2, bare.height / 20);
    // Gone after its pass.
    EXPECT_EQ(changed_box(45, without.render(45)).area(), 0);
}

// A skin-coloured wall and a wooden desk are of the hand's hue: their mean colour's hue is
// within 25 degrees of the hand's, behind the hand in every rendering.
TEST(SceneRenderer, LookalikeBackgroundsHaveTheHandsHue) {
    for (const char* name : {"skinwall", "desk"}) {
        for (const std::uint32_t seed : {7U, 11U, 13U}) {
            SceneSpec s = preset(name);
            s.seed = seed;
            s.empty_seconds = 10;
            s.seconds = 1;
            s.noise_sigma = 0;
            cv::Mat hsv;
            cv::cvtColor(Renderer(s).render(0).bgr, hsv, cv::COLOR_BGR2HSV);
            const double hue = cv::mean(hsv)[0] * 2;  // OpenCV's hue is degrees / 2
            EXPECT_NEAR(hue, 22.0, 25.0) << name << " seed " << seed;
        }
    }
}

}  // namespace
