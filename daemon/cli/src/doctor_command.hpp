// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint doctor`: checks what `raypoint run` needs (the configuration, a webcam, /dev/uinput,
// the session, the service) and prints the fix for each failure. Exit 0 when all pass.
int doctor_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
