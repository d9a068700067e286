// SPDX-License-Identifier: MIT
// The whole core, frame in -> position out (Tracker::process), in the steady state of a
// tracked target: every input size and format, each instruction set at 640x480, and the
// estimator's n, y, m around the defaults at 640x480 BGR (target: <= 150 us at 640x480,
// docs/performance.md); and every combination of the filter's and the edges' sets at 640x480
// (what InstructionTrial chooses from). BM_TrackerIdle: the same at 640x480 with nobody in
// view, the tracker SEARCHING (what a daemon costs while idle).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bench_frames.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::bench {
namespace {

using core::InstructionSet;

constexpr int clip_frames = 32;

// {width, height, format, instruction set, n, y, m}.
void tracker_arguments(benchmark::internal::Benchmark* b) {
    b->ArgNames({"w", "h", "yuyv", "isa", "n", "y", "m"});
    const auto best = static_cast<long>(core::best_instruction_set());
    const core::EstimatorSettings defaults;
    const long n = defaults.rays;
    const long y = defaults.recasts;
    const long m = defaults.block_size;
    for (const auto& size : input_sizes) {
        for (const long format : {0L, 1L})
            b->Args({size[0], size[1], format, best, n, y, m});
    }
    for (long isa = 0; isa < best; ++isa) {
        for (const long format : {0L, 1L})
            b->Args({640, 480, format, isa, n, y, m});
    }
    for (const long rays : {8L, 12L, 24L, 32L})
        b->Args({640, 480, 0, best, rays, y, m});
    for (const long levels : {1L, 3L})
        b->Args({640, 480, 0, best, n, levels, m});
    for (const long block : {4L, 16L})
        b->Args({640, 480, 0, best, n, y, block});
}

// The steady state of a tracked target at `size`: warmed up into TRACKING first.
void run_tracker(benchmark::State& state, cv::Size size, long format,
                 core::StageInstructions instructions, const core::EstimatorSettings& estimator) {
    const Clip clip(size, format_argument(format), clip_frames);
    core::Settings settings;
    settings.tracking.startup_seconds = 0.0;
    settings.estimator = estimator;
    core::Tracker tracker(settings, instructions);
    long index = 0;
    for (; index < clip_frames; ++index)
        tracker.process(clip.view(index));
    long tracked = 0;
    for (auto _ : state) {
        const core::FrameResult result = tracker.process(clip.view(index++));
        tracked += result.has_position ? 1 : 0;
        benchmark::DoNotOptimize(result);
    }
    const std::string sets = instructions.filter == instructions.edges
                                 ? std::string(core::to_string(instructions.filter))
                                 : "filter " + std::string(core::to_string(instructions.filter)) +
                                       " edges " + std::string(core::to_string(instructions.edges));
    state.SetLabel(std::string(format_name(clip.view(0).format)) + " " + sets);
    state.counters["tracked"] =
        static_cast<double>(tracked) / static_cast<double>(state.iterations());
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Tracker(benchmark::State& state) {
    core::EstimatorSettings estimator;
    estimator.rays = static_cast<int>(state.range(4));
    estimator.recasts = static_cast<int>(state.range(5));
    estimator.block_size = static_cast<int>(state.range(6));
    run_tracker(
        state, {static_cast<int>(state.range(0)), static_cast<int>(state.range(1))}, state.range(2),
        core::StageInstructions::both(static_cast<InstructionSet>(state.range(3))), estimator);
}

// {format, filter set, edge set}: every combination the CPU runs, at 640x480 with the default
// estimator (the candidates of InstructionTrial).
void stage_set_arguments(benchmark::internal::Benchmark* b) {
    b->ArgNames({"yuyv", "filter", "edges"});
    const auto best = static_cast<long>(core::best_instruction_set());
    for (const long format : {0L, 1L}) {
        for (long filter = 0; filter <= best; ++filter) {
            for (long edges = 0; edges <= best; ++edges)
                b->Args({format, filter, edges});
        }
    }
}

void BM_TrackerStageSets(benchmark::State& state) {
    run_tracker(
        state, {640, 480}, state.range(0),
        {static_cast<InstructionSet>(state.range(1)), static_cast<InstructionSet>(state.range(2))},
        core::EstimatorSettings{});
}

// A still scene: the clip's first frame, copied into clip_frames buffers played in turn (one
// buffer fed again and again would stay cached, unlike a camera's) and stamped at 30 fps. No
// movement, so the tracker stays SEARCHING and skips the edge stage. Arguments: 0 = BGR,
// 1 = YUYV; `edges` 1 runs the edge stage on every frame all the same
// (Tracker::ensure_edges()), as the tracker did on every frame before it was deferred.
void BM_TrackerIdle(benchmark::State& state) {
    const bool edges = state.range(1) != 0;
    const Clip clip({640, 480}, format_argument(state.range(0)), 1);
    const core::FrameView first = clip.view(0);
    std::vector<cv::Mat> copies;
    copies.reserve(clip_frames);
    for (int i = 0; i < clip_frames; ++i) {
        copies.push_back(
            cv::Mat(first.height, first.stride, CV_8U, const_cast<std::uint8_t*>(first.data))
                .clone());
    }
    core::Settings settings;
    settings.tracking.startup_seconds = 0.0;
    core::Tracker tracker(settings);
    core::FrameView frame = first;
    long index = 0;
    long searching = 0;
    for (auto _ : state) {
        frame.data = copies[static_cast<std::size_t>(index % clip_frames)].data;
        frame.timestamp = ++index * 33'333;
        const core::FrameResult result = tracker.process(frame);
        if (edges) tracker.ensure_edges();
        searching += result.state == core::TrackerState::searching ? 1 : 0;
        benchmark::DoNotOptimize(result);
    }
    state.SetLabel(std::string(format_name(frame.format)) + " " +
                   std::string(core::to_string(tracker.instructions().filter)));
    state.counters["searching"] =
        static_cast<double>(searching) / static_cast<double>(state.iterations());
    state.counters["fps"] =
        benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_Tracker)->Apply(tracker_arguments);
BENCHMARK(BM_TrackerStageSets)->Apply(stage_set_arguments);
BENCHMARK(BM_TrackerIdle)->ArgNames({"yuyv", "edges"})->ArgsProduct({{0, 1}, {0, 1}});

}  // namespace raypoint::bench

BENCHMARK_MAIN();
