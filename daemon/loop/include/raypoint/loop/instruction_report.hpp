// SPDX-License-Identifier: MIT
#pragma once
// The text of an instruction-set trial's outcome (core::InstructionTrial), as the daemon's log,
// `raypoint ctl status` and `raypoint doctor` state it.

#include <string>

#include "raypoint/core/instruction_trial.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::daemon {

// One frame of a trial: processed with the trial's next candidate, its cost measured on the
// steady clock and recorded. Only tracker.process is timed (capture and output cost the same
// whatever the sets), and the edge stage with it: the trial runs while INITIALIZING, whose frames
// otherwise skip edges, and the edge sets must be measured too. Allocates nothing.
core::FrameResult process_in_trial(core::Tracker& tracker, core::InstructionTrial& trial,
                                   const core::FrameView& frame) noexcept;

// "filter sse2, edges avx2"
std::string describe_instructions(core::StageInstructions instructions);

// The choice and why: "filter sse2, edges avx2 (measured over 54 frames, median us a frame by
// filter/edges: scalar/scalar 460, ...)", or "(set by [tracking] instructions)", or "(the only
// set this CPU runs)". `forced`: the trial was made with a set from the configuration.
std::string describe_trial(const core::InstructionTrial& trial, bool forced);

}  // namespace raypoint::daemon
