// SPDX-License-Identifier: MIT
#pragma once
// The service binary `raypoint` links no video reader (recorded_source.hpp explains why); the
// commands that need one are run by raypoint-tools, found beside the running executable (the
// build tree) or in the installed libexec directory.

#include <span>
#include <string_view>

namespace raypoint::daemon {

// True for track, demo, compare-estimators, bench, eval-clicks, plot, preview, setup,
// and run with --input; false with --help.
bool needs_video_tools(std::span<const std::string_view> args);

// Replaces this process by raypoint-tools with the same arguments. Returns only on failure,
// after saying on stderr which paths were tried and why they failed: the exit code then (127).
int exec_video_tools(char** argv);

}  // namespace raypoint::daemon
