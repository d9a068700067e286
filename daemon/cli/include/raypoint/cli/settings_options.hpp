// SPDX-License-Identifier: MIT
#pragma once
// The options every command that runs the core shares: --config, --preset, --set, --estimator.

#include <filesystem>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "raypoint/config/config.hpp"

namespace raypoint::daemon {

// Builds the configuration from the shared options in `args`, in this order: the preset
// (--preset NAME wherever it stands, else the file's [general] preset, else "default"), the file
// (--config FILE, else `default_file` when given), then --estimator NAME and every
// --set section.key=value in order, so the command line wins. The other arguments are returned in
// order. Throws UsageError, or config::InvalidConfig with every error of the file or every failed
// cross-check.
config::Config parse_settings_options(
    std::span<const std::string_view> args, std::vector<std::string_view>& rest,
    const std::optional<std::filesystem::path>& default_file = std::nullopt);

// The value of --config in `args`, if any; throws UsageError when it is given twice or without
// a value.
std::optional<std::filesystem::path> config_option(std::span<const std::string_view> args);

// The value after option args[i]; throws UsageError when it is missing.
std::string_view option_value(std::span<const std::string_view> args, std::size_t& i);

}  // namespace raypoint::daemon
