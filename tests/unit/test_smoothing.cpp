// SPDX-License-Identifier: MIT
// Output smoothing (paper 4.3): the exponential average, once a frame or on frame time, and the
// One Euro filter.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/core/smoothing.hpp"

namespace raypoint::core {
namespace {

constexpr Timestamp frame_us = 33'333;  // 30 fps

// Once a frame, as the paper.
OutputSettings ema_settings() {
    OutputSettings settings;
    settings.smoothing = SmoothingKind::ema;
    settings.ema_weight = 0.9;
    settings.ema_frame_rate = 0.0;
    return settings;
}

// ema_weight a 1/rate s of frame time: 10 a second, so 100 ms intervals give whole powers.
OutputSettings ema_on_frame_time(double rate) {
    OutputSettings settings = ema_settings();
    settings.ema_frame_rate = rate;
    return settings;
}

TEST(Ema, NinetyPercentOldTenPercentNewEachFrame) {
    PositionSmoother smoother(ema_settings());
    smoother.reset({0.0, 0.0, 0.0}, 0);
    // 0.9 * 0 + 0.1 * (10, 20, 30) = (1, 2, 3)
    cv::Point3d p = smoother.update({10.0, 20.0, 30.0}, frame_us);
    EXPECT_DOUBLE_EQ(p.x, 1.0);
    EXPECT_DOUBLE_EQ(p.y, 2.0);
    EXPECT_DOUBLE_EQ(p.z, 3.0);
    // 0.9 * (1, 2, 3) + 0.1 * (10, 20, 30) = (1.9, 3.8, 5.7)
    p = smoother.update({10.0, 20.0, 30.0}, 2 * frame_us);
    EXPECT_DOUBLE_EQ(p.x, 1.9);
    EXPECT_DOUBLE_EQ(p.y, 3.8);
    EXPECT_DOUBLE_EQ(p.z, 5.7);
    // 0.9 * (1.9, 3.8, 5.7) + 0.1 * (-10, 0, 5) = (0.71, 3.42, 5.63)
    p = smoother.update({-10.0, 0.0, 5.0}, 3 * frame_us);
    EXPECT_DOUBLE_EQ(p.x, 0.71);
    EXPECT_DOUBLE_EQ(p.y, 3.42);
    EXPECT_DOUBLE_EQ(p.z, 5.63);
}

TEST(Ema, OnceAFrameWhateverTheTimestamps) {
    // The paper's average runs per frame: a 1 ms gap and a 1 s gap weigh the same.
    PositionSmoother fast(ema_settings());
    PositionSmoother slow(ema_settings());
    fast.reset({0.0, 0.0, 0.0}, 0);
    slow.reset({0.0, 0.0, 0.0}, 0);
    for (int i = 1; i <= 5; ++i) {
        const cv::Point3d a = fast.update({1.0, 1.0, 1.0}, i * 1'000);
        const cv::Point3d b = slow.update({1.0, 1.0, 1.0}, i * 1'000'000);
        EXPECT_DOUBLE_EQ(a.x, b.x);
        // After i frames of 1 from 0: 1 - 0.9^i.
        EXPECT_NEAR(a.x, 1.0 - std::pow(0.9, i), 1e-12);
    }
}

TEST(Ema, OnFrameTimeALongIntervalWeighsAsTheFramesItStandsFor) {
    // A camera at 10 fps, and the same camera dropping frames: one frame 300 ms after the last
    // moves the average as far as three frames 100 ms apart with the same estimate.
    PositionSmoother every(ema_on_frame_time(10.0));
    PositionSmoother dropped(ema_on_frame_time(10.0));
    every.reset({0.0, 0.0, 0.0}, 0);
    dropped.reset({0.0, 0.0, 0.0}, 0);
    EXPECT_NEAR(every.update({1.0, 2.0, 3.0}, 100'000).x, 0.1, 1e-12);
    every.update({1.0, 2.0, 3.0}, 200'000);
    const cv::Point3d a = every.update({1.0, 2.0, 3.0}, 300'000);
    const cv::Point3d b = dropped.update({1.0, 2.0, 3.0}, 300'000);
    EXPECT_NEAR(a.x, 1.0 - 0.729, 1e-12);  // 1 - 0.9^3
    EXPECT_NEAR(b.x, a.x, 1e-12);
    EXPECT_NEAR(b.y, a.y, 1e-12);
    EXPECT_NEAR(b.z, a.z, 1e-12);
}

TEST(Ema, OnFrameTimeTheLagInSecondsIsTheSameAtSlowerFrameRates) {
    // 95% of a step in 0.95 s at the default 30 a second, whether the camera gives 30 fps or 6.
    OutputSettings settings;
    ASSERT_EQ(settings.ema_frame_rate, 30.0);
    auto after_a_second = [&](int fps) {
        PositionSmoother smoother(settings);
        smoother.reset({0.0, 0.0, 0.0}, 0);
        double x = 0.0;
        for (int i = 1; i <= fps; ++i)
            x = smoother.update({1.0, 0.0, 0.0}, i * 1'000'000LL / fps).x;
        return x;
    };
    for (const int fps : {15, 6})
        EXPECT_NEAR(after_a_second(fps), 1.0 - std::pow(0.9, 30), 1e-9) << fps << " fps";
    // 30 fps in whole microseconds is 33333 and 33334 us, and a frame closer than 1/30 s weighs
    // a whole frame: within 1e-5 of the same.
    EXPECT_NEAR(after_a_second(30), 1.0 - std::pow(0.9, 30), 1e-5);
}

TEST(Ema, OnFrameTimeAFasterCameraKeepsTheWeightAFrame) {
    // At 60 fps with the default 30 a second: 0.9 a frame, as the paper, so the lag in seconds
    // is half that at 30 fps (95% of a step in 30 frames, 0.5 s).
    OutputSettings settings;
    PositionSmoother smoother(settings);
    smoother.reset({0.0, 0.0, 0.0}, 0);
    double x = 0.0;
    for (int i = 1; i <= 30; ++i)
        x = smoother.update({1.0, 0.0, 0.0}, i * 1'000'000LL / 60).x;
    EXPECT_NEAR(x, 1.0 - std::pow(0.9, 30), 1e-9);
}

TEST(Ema, WeightForAnInterval) {
    EXPECT_DOUBLE_EQ(ema_weight_after(ema_settings(), 1.0), 0.9);  // once a frame: any interval
    EXPECT_DOUBLE_EQ(ema_weight_after(ema_on_frame_time(10.0), 0.2), 0.9 * 0.9);
    // Frames closer than 1/rate: the weight a frame, as once a frame.
    EXPECT_DOUBLE_EQ(ema_weight_after(ema_on_frame_time(10.0), 0.05), 0.9);
    EXPECT_DOUBLE_EQ(ema_weight_after(ema_on_frame_time(10.0), 0.15), std::pow(0.9, 1.5));
    // No interval (a first frame, a repeated timestamp): one frame's weight.
    EXPECT_DOUBLE_EQ(ema_weight_after(ema_on_frame_time(10.0), 0.0), 0.9);
}

TEST(Ema, WeightIsASetting) {
    OutputSettings settings = ema_settings();
    settings.ema_weight = 0.5;
    PositionSmoother smoother(settings);
    smoother.reset({4.0, 0.0, 0.0}, 0);
    EXPECT_DOUBLE_EQ(smoother.update({8.0, 0.0, 0.0}, frame_us).x, 6.0);  // 0.5*4 + 0.5*8
}

TEST(OneEuro, ConstantInputStaysConstant) {
    OneEuroFilter filter(1.0, 0.5, 1.0);
    filter.reset(3.25, 0);
    for (int i = 1; i <= 100; ++i)
        EXPECT_EQ(filter.update(3.25, i * frame_us), 3.25);
}

TEST(OneEuro, StepConvergesMonotonically) {
    OneEuroFilter filter(1.0, 0.5, 1.0);
    filter.reset(0.0, 0);
    double previous = 0.0;
    double value = 0.0;
    for (int i = 1; i <= 300; ++i) {  // 10 s at 30 fps
        value = filter.update(1.0, i * frame_us);
        if (i <= 30) {
            ASSERT_GT(value, previous) << "frame " << i;
        } else {
            ASSERT_GE(value, previous) << "frame " << i;  // may reach 1.0 exactly
        }
        ASSERT_LE(value, 1.0) << "frame " << i;
        if (i == 1) {
            // A low-pass, not a pass-through: the first frame moves only part of the way.
            EXPECT_LT(value, 0.9);
        }
        previous = value;
    }
    EXPECT_NEAR(value, 1.0, 1e-3);
}

TEST(OneEuro, AtRestTheCutoffIsMinCutoff) {
    // The first sample of a step from rest: the derivative filter has seen one raw derivative
    // d = 1 / dt; with beta = 0 the value cutoff is min_cutoff whatever d is. tau = 1 / (2 pi f),
    // alpha = 1 / (1 + tau / dt). f = 1 Hz, dt = 0.1 s: tau = 0.159155, alpha = 0.385869.
    OneEuroFilter filter(1.0, 0.0, 1.0);
    filter.reset(0.0, 0);
    const double tau = 1.0 / (2.0 * M_PI);
    EXPECT_NEAR(filter.update(1.0, 100'000), 1.0 / (1.0 + tau / 0.1), 1e-12);
}

double lag_on_ramp(double beta) {
    // A ramp of 1 unit a second for 2 s at 30 fps; the lag is how far behind the filter ends.
    OneEuroFilter filter(1.0, beta, 1.0);
    filter.reset(0.0, 0);
    double out = 0.0;
    double in = 0.0;
    for (int i = 1; i <= 60; ++i) {
        in = i / 30.0;
        out = filter.update(in, i * frame_us);
    }
    return in - out;
}

TEST(OneEuro, HigherBetaLagsLessOnARamp) {
    const double still = lag_on_ramp(0.0);
    const double some = lag_on_ramp(1.0);
    const double lots = lag_on_ramp(20.0);
    EXPECT_GT(still, 0.1);  // 1 Hz cutoff: about 1 / (2 pi) s behind a 1/s ramp, 0.16
    EXPECT_LT(some, still);
    EXPECT_LT(lots, some);
    EXPECT_GT(lots, 0.0);
}

TEST(OneEuro, RepeatedTimestampReturnsThePreviousValue) {
    OneEuroFilter filter(1.0, 0.5, 1.0);
    filter.reset(0.0, 0);
    const double first = filter.update(10.0, frame_us);
    EXPECT_EQ(filter.update(-500.0, frame_us), first);
    EXPECT_EQ(filter.update(-500.0, frame_us - 10), first);  // earlier: also ignored
    // The ignored samples left no trace: the next frame continues from `first`.
    OneEuroFilter reference(1.0, 0.5, 1.0);
    reference.reset(0.0, 0);
    reference.update(10.0, frame_us);
    EXPECT_EQ(filter.update(10.0, 2 * frame_us), reference.update(10.0, 2 * frame_us));
}

TEST(PositionSmoother, ResetForgetsThePreviousTarget) {
    PositionSmoother smoother(ema_settings());
    smoother.reset({100.0, 100.0, 100.0}, 0);
    smoother.update({100.0, 100.0, 100.0}, frame_us);
    smoother.reset({0.0, 0.0, 0.0}, 2 * frame_us);
    const cv::Point3d p = smoother.update({10.0, 20.0, 30.0}, 3 * frame_us);
    EXPECT_DOUBLE_EQ(p.x, 1.0);  // from 0, not from 100
    EXPECT_DOUBLE_EQ(p.y, 2.0);
    EXPECT_DOUBLE_EQ(p.z, 3.0);
}

TEST(PositionSmoother, OneEuroPerAxisAndReset) {
    OutputSettings settings;
    settings.smoothing = SmoothingKind::one_euro;
    PositionSmoother smoother(settings);
    smoother.reset({1.0, 2.0, 3.0}, 0);
    // Constant input: each axis stays where it was reset.
    cv::Point3d p = smoother.update({1.0, 2.0, 3.0}, frame_us);
    EXPECT_EQ(p, cv::Point3d(1.0, 2.0, 3.0));
    // A step on x only moves x, part of the way.
    p = smoother.update({2.0, 2.0, 3.0}, 2 * frame_us);
    EXPECT_GT(p.x, 1.0);
    EXPECT_LT(p.x, 2.0);
    EXPECT_EQ(p.y, 2.0);
    EXPECT_EQ(p.z, 3.0);
    // The same step after a reset to the new place is no step at all.
    smoother.reset({2.0, 2.0, 3.0}, 3 * frame_us);
    EXPECT_EQ(smoother.update({2.0, 2.0, 3.0}, 4 * frame_us).x, 2.0);
    // Per-axis filters agree with a lone OneEuroFilter on the same samples.
    OneEuroFilter alone(settings.one_euro_min_cutoff, settings.one_euro_beta,
                        settings.one_euro_d_cutoff);
    alone.reset(2.0, 3 * frame_us);
    alone.update(2.0, 4 * frame_us);
    EXPECT_EQ(smoother.update({5.0, 2.0, 3.0}, 5 * frame_us).x, alone.update(5.0, 5 * frame_us));
}

}  // namespace
}  // namespace raypoint::core
