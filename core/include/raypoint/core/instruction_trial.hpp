// SPDX-License-Identifier: MIT
#pragma once
// Chooses each preprocessing stage's instruction set by measurement: every combination of the
// sets the CPU runs (filter x edges, at most 3 x 3) is used in turn, frame by frame, and the
// one with the smallest median frame cost wins. The caller owns the clock: it runs a frame
// with next_candidate(), measures it and hands the duration to record(). The sets give the
// same images bit for bit, so a trial changes nothing but the time (docs/performance.md,
// "Choosing the instruction set").
//
// Whole combinations rather than stage after stage: the edge stage reads the planes the filter
// has just written, so one stage's set can change the other's cost (cache state, AVX clock
// changes on some CPUs), and a product of 9 still fits the frames INITIALIZING discards anyway.

#include <array>
#include <optional>

#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/stage_instructions.hpp"

namespace raypoint::core {

class InstructionTrial {
  public:
    static constexpr int max_candidates = 9;  // 3 filter sets x 3 edge sets
    static constexpr int max_samples = 32;    // per candidate
    // 54 frames: 1.8 s at 30 fps, inside the 2 s of INITIALIZING (paper 4.2) whose frames the
    // tracker does nothing useful with; 6 samples a candidate when there are 9.
    static constexpr int default_frames = 54;

    // `forced`: that set for both stages (clamped to `best`), nothing measured. Otherwise every
    // combination of the sets up to `best` (best_instruction_set()), over about `frames` frames
    // (at least one sample a candidate). A single candidate needs no measuring either.
    explicit InstructionTrial(InstructionSet best, std::optional<InstructionSet> forced = {},
                              int frames = default_frames) noexcept;

    // The sets for the next frame: the candidates in turn, so that a change of load (another
    // process, the CPU's clock) hits all of them alike. After done(): chosen().
    StageInstructions next_candidate() const noexcept;
    // The cost of the frame run with next_candidate(), in microseconds. Ignored after done().
    void record(double microseconds) noexcept;
    bool done() const noexcept { return recorded_ >= candidate_count_ * samples_; }
    // The candidate with the smallest median cost (ties: the earlier, narrower one); before
    // done() the best by the samples so far.
    StageInstructions chosen() const noexcept;

    // True when the sets were set rather than measured (a forced set, or one candidate).
    bool measured() const noexcept { return samples_ > 0; }
    int candidate_count() const noexcept { return candidate_count_; }
    StageInstructions candidate(int index) const noexcept;
    // The median of candidate `index`'s samples, microseconds; 0 without samples.
    double median(int index) const noexcept;
    int frames_recorded() const noexcept { return recorded_; }

  private:
    std::array<StageInstructions, max_candidates> candidates_{};
    // Per candidate, its samples in the order measured.
    std::array<std::array<double, max_samples>, max_candidates> samples_by_candidate_{};
    int candidate_count_ = 1;
    int samples_ = 0;  // per candidate; 0: nothing to measure
    int recorded_ = 0;
};

}  // namespace raypoint::core
