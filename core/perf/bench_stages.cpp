// SPDX-License-Identifier: MIT
// Per-stage cost of preprocessing (paper 4.1): Poisson-disk filter + subsampling, Sobel edges,
// difference + brightness compensation; every input size and format, and each instruction set
// at 640x480. The stages after the filter work on the 160x120 working image only. The bounds
// beside them: BM_FrameRead copies each frame of the same loop (what reading a frame costs at
// the least), BM_FilterCached filters one frame again and again (the filter's arithmetic and
// loads with the frame in cache).

#include <benchmark/benchmark.h>

#include <cstring>
#include <string>
#include <vector>

#include "bench_frames.hpp"
#include "raypoint/core/preprocess.hpp"

namespace raypoint::bench {
namespace {

using core::InstructionSet;

constexpr int clip_frames = 32;

// {width, height, format, instruction set, source (edges, movement: 0 luma, 1 max_channel)}.
void stage_arguments(benchmark::internal::Benchmark* b) {
    b->ArgNames({"w", "h", "yuyv", "isa", "src"});
    const auto best = static_cast<long>(core::best_instruction_set());
    for (const auto& size : input_sizes) {
        for (const long format : {0L, 1L})
            b->Args({size[0], size[1], format, best, 1});
    }
    for (long isa = 0; isa < best; ++isa) {
        for (const long format : {0L, 1L})
            b->Args({640, 480, format, isa, 1});
    }
    b->Args({640, 480, 0, best, 0});  // the paper's grey-only edges and movement
}

struct Setup {
    explicit Setup(const benchmark::State& state)
        : clip({static_cast<int>(state.range(0)), static_cast<int>(state.range(1))},
               format_argument(state.range(2)), clip_frames),
          instructions(static_cast<InstructionSet>(state.range(3))),
          preprocessor(settings(state.range(4)), core::StageInstructions::both(instructions)) {}

    static core::PreprocessSettings settings(long source) {
        core::PreprocessSettings s;
        s.edge_source = source == 0 ? core::EdgeSource::luma : core::EdgeSource::max_channel;
        s.movement_source = s.edge_source;
        return s;
    }

    void label(benchmark::State& state) const {
        state.SetLabel(std::string(format_name(clip.view(0).format)) + " " +
                       std::string(core::to_string(instructions)) +
                       (state.range(4) == 0 ? " luma" : ""));
    }

    Clip clip;
    InstructionSet instructions;
    core::Preprocessor preprocessor;
};

// Each frame of the loop is new to the cache's nearest levels, as a camera's buffer is.
void BM_FilterSubsample(benchmark::State& state) {
    Setup setup(state);
    long index = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(setup.preprocessor.filter(setup.clip.view(index++)));
    }
    setup.label(state);
    state.counters["input_MB/s"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * setup.clip.view(0).stride *
                               setup.clip.size().height / 1e6,
                           benchmark::Counter::kIsRate);
}

void BM_Sobel(benchmark::State& state) {
    Setup setup(state);
    setup.preprocessor.filter(setup.clip.view(0));
    for (auto _ : state) {
        setup.preprocessor.compute_edges();
        benchmark::DoNotOptimize(setup.preprocessor.edges().data);
    }
    setup.label(state);
}

void BM_DifferenceCompensation(benchmark::State& state) {
    Setup setup(state);
    setup.preprocessor.filter(setup.clip.view(0));
    setup.preprocessor.filter(setup.clip.view(3));
    for (auto _ : state) {
        setup.preprocessor.compute_difference();
        benchmark::DoNotOptimize(setup.preprocessor.movement());
    }
    setup.label(state);
}

// The memory bound of the filter: every byte of each frame of the loop read once (memcpy into
// one buffer that stays in cache).
void BM_FrameRead(benchmark::State& state) {
    Setup setup(state);
    const core::FrameView first = setup.clip.view(0);
    const auto bytes =
        static_cast<std::size_t>(first.stride) * static_cast<std::size_t>(first.height);
    std::vector<std::uint8_t> copy(bytes);
    long index = 0;
    for (auto _ : state) {
        std::memcpy(copy.data(), setup.clip.view(index++).data, bytes);
        benchmark::DoNotOptimize(copy.data());
        benchmark::ClobberMemory();
    }
    setup.label(state);
}

// The filter's compute bound: the same frame each time, so it stays in cache.
void BM_FilterCached(benchmark::State& state) {
    Setup setup(state);
    for (auto _ : state) {
        benchmark::DoNotOptimize(setup.preprocessor.filter(setup.clip.view(0)));
    }
    setup.label(state);
}

// All three, as the tracker runs them.
void BM_Preprocess(benchmark::State& state) {
    Setup setup(state);
    long index = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(setup.preprocessor.process(setup.clip.view(index++)));
    }
    setup.label(state);
}

}  // namespace

BENCHMARK(BM_FilterSubsample)->Apply(stage_arguments);
BENCHMARK(BM_Sobel)->Apply(stage_arguments);
BENCHMARK(BM_DifferenceCompensation)->Apply(stage_arguments);
BENCHMARK(BM_Preprocess)->Apply(stage_arguments);
BENCHMARK(BM_FrameRead)->Apply(stage_arguments);
BENCHMARK(BM_FilterCached)->Apply(stage_arguments);

}  // namespace raypoint::bench
