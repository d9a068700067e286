// SPDX-License-Identifier: MIT
// InstructionTrial on given durations: which combination it picks, the order it measures them
// in, and a forced set.

#include <vector>

#include <gtest/gtest.h>

#include "raypoint/core/instruction_trial.hpp"

namespace raypoint::core {
namespace {

constexpr InstructionSet scalar = InstructionSet::scalar;
constexpr InstructionSet sse2 = InstructionSet::sse2;
constexpr InstructionSet avx2 = InstructionSet::avx2;

// A made-up CPU: the filter is cheapest with SSE2 (as on AMD Zen 3), the edges with AVX2.
double cost(StageInstructions sets) {
    const double filter[] = {290.0, 155.0, 272.0};
    const double edges[] = {40.0, 40.0, 25.0};
    return filter[static_cast<int>(sets.filter)] + edges[static_cast<int>(sets.edges)];
}

TEST(InstructionTrial, EveryCombinationTheCpuRunsIsACandidate) {
    const InstructionTrial avx2_cpu(avx2);
    EXPECT_EQ(avx2_cpu.candidate_count(), 9);
    EXPECT_TRUE(avx2_cpu.measured());
    const InstructionTrial sse2_cpu(sse2);
    ASSERT_EQ(sse2_cpu.candidate_count(), 4);
    for (int i = 0; i < sse2_cpu.candidate_count(); ++i) {
        EXPECT_LE(sse2_cpu.candidate(i).filter, sse2);
        EXPECT_LE(sse2_cpu.candidate(i).edges, sse2);
    }
    // One candidate: nothing to measure.
    const InstructionTrial scalar_cpu(scalar);
    EXPECT_TRUE(scalar_cpu.done());
    EXPECT_FALSE(scalar_cpu.measured());
    EXPECT_EQ(scalar_cpu.chosen(), StageInstructions::both(scalar));
}

TEST(InstructionTrial, RotatesTheCandidatesFrameByFrame) {
    InstructionTrial trial(avx2, {}, 27);  // 3 samples of each of 9
    std::vector<StageInstructions> first_round;
    for (int i = 0; i < 9; ++i) {
        first_round.push_back(trial.next_candidate());
        trial.record(100.0);
    }
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < i; ++j)
            EXPECT_NE(first_round[i], first_round[j]);  // every candidate once in a round
    }
    for (int round = 1; round < 3; ++round) {
        for (int i = 0; i < 9; ++i) {
            EXPECT_FALSE(trial.done());
            EXPECT_EQ(trial.next_candidate(), first_round[i]);  // the same order again
            trial.record(100.0);
        }
    }
    EXPECT_TRUE(trial.done());
    EXPECT_EQ(trial.frames_recorded(), 27);
}

TEST(InstructionTrial, PicksTheSmallestMedianCost) {
    InstructionTrial trial(avx2);
    int frames = 0;
    while (!trial.done()) {
        const StageInstructions sets = trial.next_candidate();
        // Every candidate's first sample is a slow outlier (a first frame, a page fault):
        // the median ignores it.
        trial.record(cost(sets) + (frames < 9 ? 5000.0 : static_cast<double>(frames % 3)));
        ++frames;
    }
    EXPECT_EQ(frames, InstructionTrial::default_frames);
    EXPECT_EQ(trial.chosen(), (StageInstructions{sse2, avx2}));
    EXPECT_EQ(trial.next_candidate(), trial.chosen());  // after the trial: the choice
    for (int i = 0; i < trial.candidate_count(); ++i)
        EXPECT_NEAR(trial.median(i), cost(trial.candidate(i)), 2.0);
    // More samples change nothing once done.
    trial.record(1.0);
    EXPECT_EQ(trial.frames_recorded(), frames);
}

TEST(InstructionTrial, AForcedSetIsUsedForBothStagesWithoutMeasuring) {
    const InstructionTrial forced(avx2, scalar);
    EXPECT_TRUE(forced.done());
    EXPECT_FALSE(forced.measured());
    EXPECT_EQ(forced.next_candidate(), StageInstructions::both(scalar));
    EXPECT_EQ(forced.chosen(), StageInstructions::both(scalar));
    // A set the CPU does not have is clamped to the widest it has.
    const InstructionTrial clamped(sse2, avx2);
    EXPECT_EQ(clamped.chosen(), StageInstructions::both(sse2));
    EXPECT_EQ(clamp_instruction_set(avx2, sse2), sse2);
    EXPECT_EQ(clamp_instruction_set(scalar, avx2), scalar);
}

}  // namespace
}  // namespace raypoint::core
