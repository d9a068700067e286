// SPDX-License-Identifier: MIT
// The instruction-set trial: candidates in rotation, the smallest median wins.

#include "raypoint/core/instruction_trial.hpp"

#include <algorithm>

namespace raypoint::core {

InstructionTrial::InstructionTrial(InstructionSet best, std::optional<InstructionSet> forced,
                                   int frames) noexcept {
    if (forced) {
        candidates_[0] = StageInstructions::both(clamp_instruction_set(*forced, best));
        return;
    }
    candidate_count_ = 0;
    const int widest = static_cast<int>(best);
    for (int filter = 0; filter <= widest; ++filter) {
        for (int edges = 0; edges <= widest; ++edges) {
            candidates_[candidate_count_++] = {static_cast<InstructionSet>(filter),
                                               static_cast<InstructionSet>(edges)};
        }
    }
    if (candidate_count_ > 1) samples_ = std::clamp(frames / candidate_count_, 1, max_samples);
}

StageInstructions InstructionTrial::next_candidate() const noexcept {
    if (done()) return chosen();
    return candidates_[recorded_ % candidate_count_];
}

void InstructionTrial::record(double microseconds) noexcept {
    if (done()) return;
    const int index = recorded_ % candidate_count_;
    samples_by_candidate_[index][recorded_ / candidate_count_] = microseconds;
    ++recorded_;
}

double InstructionTrial::median(int index) const noexcept {
    // Candidate `index` has had one sample per full round, plus one if the current round has
    // reached it.
    const int count = recorded_ / candidate_count_ + (index < recorded_ % candidate_count_ ? 1 : 0);
    if (count == 0) return 0.0;
    std::array<double, max_samples> sorted = samples_by_candidate_[index];
    const auto begin = sorted.begin();
    std::sort(begin, begin + count);
    // The mean of the middle two for an even count.
    return (sorted[(count - 1) / 2] + sorted[count / 2]) / 2.0;
}

StageInstructions InstructionTrial::chosen() const noexcept {
    int best = 0;
    double best_median = 0.0;
    for (int i = 0; i < candidate_count_; ++i) {
        const double m = median(i);
        if (m <= 0.0) continue;  // not measured yet
        if (best_median <= 0.0 || m < best_median) {
            best = i;
            best_median = m;
        }
    }
    return candidates_[best];
}

StageInstructions InstructionTrial::candidate(int index) const noexcept {
    return candidates_[index];
}

}  // namespace raypoint::core
