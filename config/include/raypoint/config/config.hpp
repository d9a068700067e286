// SPDX-License-Identifier: MIT
#pragma once
// The whole configuration of raypoint as plain data. The daemon's settings join the core's here.

#include <optional>
#include <string>
#include <string_view>

#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::config {

// [camera]: the daemon's webcam (raypoint run). Not the core's: frames reach the core as data.
struct CameraSettings {
    std::string device = "auto";  // auto: the first capture device that streams
    // Locking auto exposure, gain and white balance removes the brightness jumps the paper works
    // around; off by default because a room's light changes over a day.
    bool lock_exposure = false;
    // The smallest frame size worth capturing (docs/performance.md, "Camera size"): 320x240
    // tracks as 640x480 does at a quarter of the bytes; 160x120 loses depth precision.
    int min_width = 320;
    int min_height = 240;
};

// [tracking] instructions: the vector instructions of preprocessing's filter and edge stages.
// automatic: measured while INITIALIZING (core::InstructionTrial); a named set: both stages,
// clamped to what the CPU runs.
enum class InstructionsSetting { automatic, scalar, sse2, avx2 };

struct Config {
    core::Settings core;
    CameraSettings camera;
    InstructionsSetting instructions = InstructionsSetting::automatic;
};

// The set `setting` names; none for automatic.
inline std::optional<core::InstructionSet> forced_instruction_set(InstructionsSetting setting) {
    switch (setting) {
        case InstructionsSetting::automatic:
            return std::nullopt;
        case InstructionsSetting::scalar:
            return core::InstructionSet::scalar;
        case InstructionsSetting::sse2:
            return core::InstructionSet::sse2;
        case InstructionsSetting::avx2:
            return core::InstructionSet::avx2;
    }
    return std::nullopt;
}

// Named starting points: "default" (measured defaults, docs/settings.md) and "paper"
// (Quesada & León exactly). Returns false for an unknown name.
bool apply_preset(Config& config, std::string_view name);

}  // namespace raypoint::config
