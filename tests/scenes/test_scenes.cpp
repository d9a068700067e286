// SPDX-License-Identifier: MIT
// Scene tests: the tracker on the project's own rendered clips (daemon/scene), scored against
// their exact truth by the scoring method (docs/scoring.md). Thresholds: the project's accuracy
// requirements where there is one (detection within 0.5 s; >= 95% on target for the ideal and
// non-convex scenes; median centroid error <= 2 px for the sphere and <= 4 px for the hand at
// 160x120; z against 1/depth r >= 0.9), otherwise what the scene measured on 2026-11-21 less a
// margin.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "raypoint/config/config.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/scene/evaluation.hpp"
#include "raypoint/scene/renderer.hpp"

namespace {

using raypoint::scene::Evaluation;

Evaluation track_scene(const raypoint::scene::SceneSpec& spec,
                       const raypoint::core::Settings& settings) {
    const raypoint::scene::Renderer renderer(spec);
    raypoint::core::Tracker tracker(settings);
    raypoint::scene::Evaluator evaluator;
    for (int index = 0; index < renderer.frame_count(); ++index) {
        const auto frame = renderer.render(index);
        const raypoint::core::FrameView view{
            frame.bgr.data,
            frame.bgr.cols,
            frame.bgr.rows,
            static_cast<int>(frame.bgr.step),
            raypoint::core::PixelFormat::bgr,
            raypoint::core::seconds_to_us(renderer.frame_time(index))};
        evaluator.add(frame.truth, frame.mask, tracker.process(view));
    }
    const Evaluation e = evaluator.result();
    std::printf(
        "%-12s tracked %5.1f%% of %d, cerr %s px, area err %s, z r %s, detected after %s s\n",
        spec.name.c_str(), 100.0 * e.tracked(), e.scored_frames,
        e.median_centroid_error ? std::to_string(*e.median_centroid_error).c_str() : "-",
        e.median_area_error ? std::to_string(*e.median_area_error).c_str() : "-",
        e.depth_correlation ? std::to_string(*e.depth_correlation).c_str() : "-",
        e.detection_delay ? std::to_string(*e.detection_delay).c_str() : "-");
    return e;
}

struct Expectation {
    const char* preset;
    double min_tracked;                 // share of moving frames on target
    double max_centroid_error;          // median, px at 160x120
    std::optional<double> min_depth_r;  // z against 1/depth
    double max_detection_delay = 0.5;   // s after the target first moves
    std::uint32_t seed = 0;             // 0: the preset's own
};

class Scene : public ::testing::TestWithParam<Expectation> {};

TEST_P(Scene, MeetsItsThresholds) {
    const Expectation& expected = GetParam();
    raypoint::scene::SceneSpec spec = raypoint::scene::preset(expected.preset);
    if (expected.seed != 0) spec.seed = expected.seed;
    const Evaluation e = track_scene(spec, raypoint::core::Settings{});
    ASSERT_GT(e.scored_frames, 20) << "the clip has too few moving frames to judge";
    ASSERT_TRUE(e.detection_delay.has_value()) << "the target was never detected";
    EXPECT_LE(*e.detection_delay, expected.max_detection_delay);
    EXPECT_GE(e.tracked(), expected.min_tracked);
    ASSERT_TRUE(e.median_centroid_error.has_value());
    EXPECT_LE(*e.median_centroid_error, expected.max_centroid_error);
    if (expected.min_depth_r) {
        ASSERT_TRUE(e.depth_correlation.has_value());
        EXPECT_GE(*e.depth_correlation, *expected.min_depth_r);
    }
}

// Measured 2026-11-21 (tracked / cerr / z r / detection): ideal 100% 0.10 0.94 0.07 s;
// nonconvex 100% 0.20 0.96 0.03 s; lowlight 100% 0.13 0.82; interfering 100% 0.23 0.93;
// realworld 100% 0.37 0.30 0.13 s; hd60 100% 0.14 1.00; exposure 100% 0.09 0.81; jpeg 100%
// 0.47 0.98; fast 98.5% 0.48 0.41; pause 100% 0.25 0.78; push 100% 0.21 0.78.
// z is smoothed once a frame (paper 4.3), so it lags fast depth changes: the scenes with
// pushes, pauses and 15 fps blur have lower r, and no threshold is asserted for them.
INSTANTIATE_TEST_SUITE_P(
    Presets, Scene,
    ::testing::Values(Expectation{"ideal", 0.95, 2.0, 0.9},      // the sphere's requirements
                      Expectation{"nonconvex", 0.95, 4.0, 0.9},  // the hand's requirements
                      Expectation{"lowlight", 0.90, 2.0, 0.7},   // 10 fps, noise, blur
                      Expectation{"interfering", 0.90, 2.0, 0.85},
                      Expectation{"hd60", 0.90, 4.0, 0.9},      // 60 fps
                      Expectation{"exposure", 0.90, 2.0, 0.7},  // brightness jumps
                      Expectation{"jpeg", 0.90, 2.0, 0.85},     // JPEG quality 35
                      Expectation{"realworld", 0.85, 4.0, std::nullopt},
                      Expectation{"fast", 0.90, 4.0, std::nullopt},   // 15 fps, strong blur
                      Expectation{"pause", 0.90, 4.0, std::nullopt},  // holds still 3.5 s
                      Expectation{"push", 0.90, 4.0, std::nullopt},
                      // Auto-exposure and white balance hunting (+-20% gain, +-10% a channel).
                      Expectation{"drift", 0.98, 1.5, 0.9},
                      // A rolling shutter's skew on realworld's hand at twice its speed.
                      Expectation{"skew", 0.98, 1.5, 0.7},
                      // Mains flicker's bands rolling through every frame, MJPEG quality 60.
                      Expectation{"flicker", 0.98, 1.5, 0.7},
                      // Skin lookalikes, measured 2026-11-26 on the rendered frames, where
                      // they meet 98% / 1.5 px: a person behind the hand (seed 7: 100% / 1.31
                      // px), a skin-coloured wall (seeds 7, 11, 17: 100% / 0.17, 0.20, 0.15
                      // px), a wooden desk (seed 7: 100% / 0.16 px), a sleeve of nearly the
                      // hand's colour (own seed, 7, 13: 100% / 0.56, 0.87, 1.10 px). The
                      // seeds where they do not yet are in docs/accuracy.md.
                      Expectation{"person", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"skinwall", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"skinwall", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"skinwall", 0.98, 1.5, std::nullopt, 0.5, 17},
                      Expectation{"desk", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"sleeve", 0.98, 1.5, std::nullopt},
                      Expectation{"sleeve", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"sleeve", 0.98, 1.5, std::nullopt, 0.5, 13},
                      // Measured 2026-11-27 on the rendered frames, all 100% on target (cerr
                      // px): sleeve at seeds 11 and 17 (0.41, 0.71), desk at 11, 13, 17 (0.11,
                      // 0.12, 0.12), person at 13 (0.49).
                      Expectation{"sleeve", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"sleeve", 0.98, 1.5, std::nullopt, 0.5, 17},
                      Expectation{"desk", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"desk", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"desk", 0.98, 1.5, std::nullopt, 0.5, 17},
                      Expectation{"person", 0.98, 1.5, std::nullopt, 0.5, 13},
                      // Measured 2026-11-28, the skin-coloured wall at its own seed: lost
                      // twice as the hand comes in, then picked at the deepest pixel of the
                      // change 0.1 s into the quiet (scored from the rendered video: 100% /
                      // 0.16 px).
                      Expectation{"skinwall", 0.98, 1.5, std::nullopt},
                      // The camera presets at other seeds, measured 2026-11-27, all 100%
                      // (cerr px at seeds 7, 11, 13, 17): drift 0.21, 0.38, 0.35, 0.20; skew
                      // 0.16, 0.49, 0.36, 0.20; flicker 0.23, 0.64, 0.36, 0.19.
                      Expectation{"drift", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"drift", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"drift", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"drift", 0.98, 1.5, std::nullopt, 0.5, 17},
                      Expectation{"skew", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"skew", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"skew", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"skew", 0.98, 1.5, std::nullopt, 0.5, 17},
                      Expectation{"flicker", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"flicker", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"flicker", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"flicker", 0.98, 1.5, std::nullopt, 0.5, 17},
                      // 15 fps with strong blur, other seeds: the fast hand's centroid lands
                      // off the hand and the estimate is too small; the recovery points find
                      // it again (tracking.recover_small; without it seeds 13 and 17 fail here).
                      Expectation{"fast", 0.98, 1.5, std::nullopt, 0.5, 7},
                      Expectation{"fast", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"fast", 0.98, 1.5, std::nullopt, 0.5, 17},
                      // A dark ball crossing behind realworld's hand every 2.5 s (the
                      // hand slowing at a turn as it passes is kept: tracking.abandon_grace).
                      Expectation{"passer", 0.98, 1.5, std::nullopt},
                      // Seeds 11, 13, 17: 100% / 0.65, 0.36, 0.18 px (2026-11-27).
                      Expectation{"passer", 0.98, 1.5, std::nullopt, 0.5, 11},
                      Expectation{"passer", 0.98, 1.5, std::nullopt, 0.5, 13},
                      Expectation{"passer", 0.98, 1.5, std::nullopt, 0.5, 17}),
    [](const ::testing::TestParamInfo<Expectation>& param) {
        std::string name(param.param.preset);
        if (param.param.seed != 0) name += "_seed_" + std::to_string(param.param.seed);
        return name;
    });

// The paper's system exactly (--preset paper) on the paper's ideal scenario, which the paper
// tracked "in every frame": it must here too.
TEST(PaperPreset, TracksTheIdealScene) {
    raypoint::config::Config config;
    ASSERT_TRUE(raypoint::config::apply_preset(config, "paper"));
    const Evaluation e = track_scene(raypoint::scene::preset("ideal"), config.core);
    EXPECT_GE(e.tracked(), 0.95);
    ASSERT_TRUE(e.median_centroid_error.has_value());
    EXPECT_LE(*e.median_centroid_error, 2.0);
}

// A still scene with only brightness jumps (auto-exposure) must never start a search.
TEST(BrightnessJumps, DoNotStartASearch) {
    raypoint::scene::SceneSpec spec = raypoint::scene::preset("exposure");
    spec.seconds = 2.3;  // before the target enters at 2.5 s
    spec.brightness_jumps = {0.4, 0.8, 1.2, 1.6, 2.0};
    raypoint::core::Settings settings;
    settings.tracking.startup_seconds = 0.1;
    const raypoint::scene::Renderer renderer(spec);
    raypoint::core::Tracker tracker(settings);
    int searched = 0;
    for (int index = 0; index < renderer.frame_count(); ++index) {
        const auto frame = renderer.render(index);
        const auto result =
            tracker.process({frame.bgr.data, frame.bgr.cols, frame.bgr.rows,
                             static_cast<int>(frame.bgr.step), raypoint::core::PixelFormat::bgr,
                             raypoint::core::seconds_to_us(renderer.frame_time(index))});
        if (result.state == raypoint::core::TrackerState::searching) ++searched;
        EXPECT_FALSE(result.has_target) << "frame " << index << " picked a target";
    }
    EXPECT_GT(searched, 50);
}

}  // namespace
