// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint track INPUT [options]`: runs the core on a recorded video and prints one line a
// frame. Returns the exit code; throws UsageError, InputError or config::ConfigError.
int track_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
