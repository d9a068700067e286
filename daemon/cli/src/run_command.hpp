// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

#include "raypoint/cli/recorded_input.hpp"

namespace raypoint::daemon {

// `raypoint run`: the daemon. Webcam (or --input FILE) in, pointer events (uinput, or
// --sink file:PATH|null) out. Returns the exit code. `recorded` opens --input clips; nullptr in
// the service binary, which links no video reader (recorded_source.hpp).
int run_command(std::span<const std::string_view> args, RecordedSourceFactory recorded);

// `raypoint ctl pause|resume|toggle|recenter|status [--json]`: talks to the running daemon.
int ctl_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
