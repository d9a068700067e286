// SPDX-License-Identifier: MIT
#pragma once
// Outputs are checked before any work starts: a command that would fail to write its result
// after minutes of tracking (or after printing half its lines) fails at once instead.

#include <string>
#include <string_view>

namespace raypoint::daemon {

// Throws std::runtime_error (exit 1) naming `option`, `path` and the reason when `path` cannot be
// created or replaced: its folder is missing, not a folder or not writable, or it is a folder.
void check_output_path(std::string_view option, const std::string& path);

}  // namespace raypoint::daemon
