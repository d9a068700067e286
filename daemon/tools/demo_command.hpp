// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint demo`: renders a scene in memory (no camera needed), tracks it, prints the 3D
// positions and how they compare with the scene's truth, and writes an annotated clip.
int demo_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
