// SPDX-License-Identifier: MIT
// Cost of estimation (paper section 3) for each estimator at and around the defaults of n
// (rays), y (levels of casting) and m (block size), and of the steps after it: the state
// machine's own logic (paper 4.2) and the pointer (position to device command).

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "bench_frames.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/state_machine.hpp"

namespace raypoint::bench {
namespace {

using core::EstimatorKind;

// {kind, n, y, m}: every estimator at the defaults, then one parameter varied at a time.
void estimator_arguments(benchmark::internal::Benchmark* b) {
    b->ArgNames({"kind", "n", "y", "m"});
    const core::EstimatorSettings defaults;
    const long n = defaults.rays;
    const long y = defaults.recasts;
    const long m = defaults.block_size;
    for (long kind = 0; kind < 4; ++kind) {
        for (const long rays : {8L, 12L, n, 24L, 32L})
            b->Args({kind, rays, y, m});
    }
    // y matters to the n^y estimators only, m to the raster one only.
    for (const long kind : {2L, 3L}) {
        for (const long levels : {1L, 3L})
            b->Args({kind, n, levels, m});
    }
    for (const long block : {4L, 16L})
        b->Args({3, n, y, block});
}

// The edge image of the clip's first 640x480 frame; estimation starts 4 working pixels off
// the disk's centre, as after a frame of motion.
void BM_Estimator(benchmark::State& state) {
    core::EstimatorSettings settings;
    settings.kind = static_cast<EstimatorKind>(state.range(0));
    settings.rays = static_cast<int>(state.range(1));
    settings.recasts = static_cast<int>(state.range(2));
    settings.block_size = static_cast<int>(state.range(3));
    const Clip clip({640, 480}, core::PixelFormat::bgr, 1);
    core::Preprocessor preprocessor{core::PreprocessSettings{}};
    preprocessor.process(clip.view(0));
    auto estimator = core::make_estimator(settings);
    const cv::Point2f start = clip.working_centre(0) - cv::Point2f(4.0F, 0.0F);
    int iterations = 0;
    for (auto _ : state) {
        const core::Estimate estimate = estimator->estimate(preprocessor.edges(), start);
        iterations = estimate.iterations;
        benchmark::DoNotOptimize(estimate);
    }
    state.SetLabel(std::string(core::to_string(settings.kind)));
    state.counters["iterations"] = iterations;
}

// Features recorded once from the estimator on the clip (a tracked disk every frame), so the
// step's own logic is what is timed: TRACKING, VALIDATING and back, as in steady state.
class RecordedEvidence final : public core::FrameEvidence {
  public:
    RecordedEvidence(const core::Estimate& estimate, cv::Vec3f colour)
        : estimate_(estimate), colour_(colour) {}
    double movement() const noexcept override { return 20'000.0; }
    double movement_near(cv::Point2f, float) const noexcept override { return 20'000.0; }
    std::optional<cv::Point2f> detect() noexcept override { return estimate_.inner; }
    core::Estimate estimate(cv::Point2f) noexcept override { return estimate_; }
    cv::Vec3f current_color(cv::Point2f) const noexcept override { return colour_; }
    cv::Vec3f previous_color(cv::Point2f) const noexcept override { return colour_; }

  private:
    core::Estimate estimate_;
    cv::Vec3f colour_;
};

void BM_StateMachineStep(benchmark::State& state) {
    const Clip clip({640, 480}, core::PixelFormat::bgr, 1);
    core::Preprocessor preprocessor{core::PreprocessSettings{}};
    preprocessor.process(clip.view(0));
    auto estimator = core::make_estimator(core::EstimatorSettings{});
    const core::Estimate estimate =
        estimator->estimate(preprocessor.edges(), clip.working_centre(0));
    const cv::Vec3b at =
        preprocessor.color().at<cv::Vec3b>(cvRound(estimate.inner.y), cvRound(estimate.inner.x));
    RecordedEvidence evidence(estimate, cv::Vec3f(at[0], at[1], at[2]));
    core::TrackingSettings settings;
    settings.startup_seconds = 0.0;
    core::StateMachine machine(settings, {160, 120});
    core::Timestamp now = 0;
    for (int i = 0; i < 3; ++i)
        machine.step(now += 33'333, evidence);  // INITIALIZING, SEARCHING, TRACKING
    for (auto _ : state) {
        benchmark::DoNotOptimize(machine.step(now += 33'333, evidence));
    }
    state.SetLabel(std::string(core::to_string(machine.state())));
}

// A tracked position moving on a circle, through the whole pointer (mapping, click by depth,
// safety rules) to a device command.
void BM_PointerMapping(benchmark::State& state) {
    core::PointerController pointer{core::PointerSettings{}};
    core::FrameResult frame;
    frame.state = core::TrackerState::tracking;
    frame.has_target = true;
    frame.has_position = true;
    long index = 0;
    for (auto _ : state) {
        const double angle = static_cast<double>(index) * 0.05;
        frame.frame = index;
        frame.timestamp = index * 33'333;
        frame.position = {0.5 + 0.1 * std::cos(angle), 0.5 + 0.1 * std::sin(angle), 0.0};
        frame.centroid = {frame.position.x, frame.position.y};
        benchmark::DoNotOptimize(pointer.update(frame));
        ++index;
    }
}

}  // namespace

BENCHMARK(BM_Estimator)->Apply(estimator_arguments);
BENCHMARK(BM_StateMachineStep);
BENCHMARK(BM_PointerMapping);

}  // namespace raypoint::bench
