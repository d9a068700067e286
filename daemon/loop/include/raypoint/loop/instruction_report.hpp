#pragma once
// The text of an instruction-set trial's outcome (core::InstructionTrial), as the daemon's log,
// `raypoint ctl status` and `raypoint doctor` state it.

#include <string>

#include "raypoint/core/instruction_trial.hpp"

namespace raypoint::daemon {

// "filter sse2, edges avx2"
std::string describe_instructions(core::StageInstructions instructions);

// The choice and why: "filter sse2, edges avx2 (measured over 54 frames, median us a frame by
// filter/edges: scalar/scalar 460, ...)", or "(set by [tracking] instructions)", or "(the only
// set this CPU runs)". `forced`: the trial was made with a set from the configuration.
std::string describe_trial(const core::InstructionTrial& trial, bool forced);

}  // namespace raypoint::daemon
