// SPDX-License-Identifier: MIT
#include "raypoint/loop/instruction_report.hpp"

#include <chrono>
#include <cmath>

namespace raypoint::daemon {

core::FrameResult process_in_trial(core::Tracker& tracker, core::InstructionTrial& trial,
                                   const core::FrameView& frame) noexcept {
    tracker.set_instructions(trial.next_candidate());
    const auto begin = std::chrono::steady_clock::now();
    const core::FrameResult result = tracker.process(frame);
    tracker.ensure_edges();
    trial.record(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - begin)
                     .count());
    return result;
}

std::string describe_instructions(core::StageInstructions instructions) {
    return "filter " + std::string(core::to_string(instructions.filter)) + ", edges " +
           std::string(core::to_string(instructions.edges));
}

std::string describe_trial(const core::InstructionTrial& trial, bool forced) {
    std::string text = describe_instructions(trial.chosen());
    if (forced) return text + " (set by [tracking] instructions)";
    if (!trial.measured()) return text + " (the only set this CPU runs)";
    text += " (measured over " + std::to_string(trial.frames_recorded()) +
            " frames, median us a frame by filter/edges:";
    for (int i = 0; i < trial.candidate_count(); ++i) {
        const core::StageInstructions sets = trial.candidate(i);
        text += std::string(i == 0 ? " " : ", ") + std::string(core::to_string(sets.filter)) + "/" +
                std::string(core::to_string(sets.edges)) + " " +
                std::to_string(std::lround(trial.median(i)));
    }
    return text + ")";
}

}  // namespace raypoint::daemon
