#pragma once
// The whole configuration of raypoint as plain data. The daemon's settings join the core's here.

#include <string>
#include <string_view>

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

struct Config {
    core::Settings core;
    CameraSettings camera;
};

// Named starting points: "default" (measured defaults, docs/settings.md) and "paper"
// (Quesada & León exactly). Returns false for an unknown name.
bool apply_preset(Config& config, std::string_view name);

}  // namespace raypoint::config
