#pragma once
// The whole configuration of raypoint as plain data. The daemon's settings join the core's here.

#include <string_view>

#include "raypoint/core/settings.hpp"

namespace raypoint::config {

struct Config {
    core::Settings core;
};

// Named starting points: "default" (measured defaults, docs/settings.md) and "paper"
// (Quesada & León exactly). Returns false for an unknown name.
bool apply_preset(Config& config, std::string_view name);

}  // namespace raypoint::config
