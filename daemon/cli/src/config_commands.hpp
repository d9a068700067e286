// SPDX-License-Identifier: MIT
#pragma once
// The commands about the configuration itself: print-config and check-config.

#include <span>
#include <string_view>

namespace raypoint::daemon {

// print-config [--defaults] [--config FILE] [--preset NAME] [--set ...]: the effective
// configuration as an INI file with every key's doc. Without --config it reads the file that
// `run` would (config::find_config_file); --defaults reads none.
int print_config_command(std::span<const std::string_view> args);

// check-config [FILE]: "FILE: ok" and 0, or every error on stderr, one a line, and 1. Without
// FILE it checks the file that `run` would read, and says which.
int check_config_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
