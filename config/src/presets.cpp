// SPDX-License-Identifier: MIT
#include "raypoint/config/config.hpp"

namespace raypoint::config {

bool apply_preset(Config& config, std::string_view name) {
    if (name == "default") {
        config.core = core::Settings{};
        return true;
    }
    if (name == "paper") {
        config.core = core::paper_settings();
        return true;
    }
    return false;
}

}  // namespace raypoint::config
