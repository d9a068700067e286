// SPDX-License-Identifier: MIT
#pragma once
// The instruction set of each dispatched preprocessing stage (paper 4.1): the filter's and the
// Sobel loops'. They are chosen apart because their costs differ by CPU (AMD Zen 3's microcoded
// gathers make the AVX2 filter slower than SSE2 while AVX2 Sobel is faster,
// docs/performance.md). Every combination gives the same images bit for bit.

#include "raypoint/core/instruction_set.hpp"

namespace raypoint::core {

struct StageInstructions {
    InstructionSet filter = InstructionSet::scalar;
    InstructionSet edges = InstructionSet::scalar;

    static StageInstructions both(InstructionSet set) noexcept { return {set, set}; }
    bool operator==(const StageInstructions&) const noexcept = default;
};

}  // namespace raypoint::core
