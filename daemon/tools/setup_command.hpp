// SPDX-License-Identifier: MIT
#pragma once
// `raypoint setup`: a guided first run that measures the user (hand size, motion range, push
// depth), proposes [pointer] gain, the active region and [click] press_rise/release_rise, lets
// them try the result in the preview and writes the INI only when they accept.

#include <span>
#include <string_view>

namespace raypoint::daemon {

int setup_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
