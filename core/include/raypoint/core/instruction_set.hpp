// SPDX-License-Identifier: MIT
#pragma once
// The widest vector instructions preprocessing may use (the filter's interior kernels and the
// Sobel loops). Every set gives the same images bit for bit; only the time differs
// (docs/performance.md).

#include <string_view>

namespace raypoint::core {

enum class InstructionSet {
    scalar,
    sse2,  // part of x86-64
    avx2,  // chosen at run time when the CPU has it
};
// The widest set this CPU runs; every narrower one runs too (x86-64 always has SSE2).
InstructionSet best_instruction_set() noexcept;
// `wanted` if the CPU whose widest set is `best` runs it, else `best`.
InstructionSet clamp_instruction_set(InstructionSet wanted, InstructionSet best) noexcept;
std::string_view to_string(InstructionSet set) noexcept;

}  // namespace raypoint::core
