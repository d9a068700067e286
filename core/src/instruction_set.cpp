// SPDX-License-Identifier: MIT
#include "raypoint/core/instruction_set.hpp"

namespace raypoint::core {

InstructionSet best_instruction_set() noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx2")) return InstructionSet::avx2;
    return InstructionSet::sse2;
#else
    return InstructionSet::scalar;
#endif
}

InstructionSet clamp_instruction_set(InstructionSet wanted, InstructionSet best) noexcept {
    return wanted <= best ? wanted : best;
}

std::string_view to_string(InstructionSet set) noexcept {
    switch (set) {
        case InstructionSet::scalar:
            return "scalar";
        case InstructionSet::sse2:
            return "sse2";
        case InstructionSet::avx2:
            return "avx2";
    }
    return "?";
}

}  // namespace raypoint::core
