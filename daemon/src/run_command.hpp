#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint run`: the daemon. Webcam (or --input FILE) in, pointer events (uinput, or
// --sink file:PATH|null) out. Returns the exit code.
int run_command(std::span<const std::string_view> args);

// `raypoint ctl pause|resume|recenter|status`: talks to the running daemon.
int ctl_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
