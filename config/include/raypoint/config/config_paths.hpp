// SPDX-License-Identifier: MIT
#pragma once
// Where raypoint looks for its configuration file when none is named (XDG Base Directory
// Specification): $XDG_CONFIG_HOME/raypoint/raypoint.ini (~/.config when unset), then
// raypoint/raypoint.ini in each of $XDG_CONFIG_DIRS (/etc/xdg when unset).

#include <filesystem>
#include <optional>
#include <vector>

namespace raypoint::config {

// Every candidate, most important first. Relative and empty entries are ignored, as the
// specification asks.
std::vector<std::filesystem::path> config_search_path();

// The first candidate that exists. A candidate that cannot be looked at (a directory without
// permission) counts as existing, so that reading it reports why instead of silently falling
// back to another file.
std::optional<std::filesystem::path> find_config_file();

}  // namespace raypoint::config
