#pragma once
// The options every command that runs the core shares: --preset, --set, --estimator.

#include <span>
#include <string_view>
#include <vector>

#include "raypoint/config/config.hpp"

namespace raypoint::daemon {

// Builds the configuration from the shared options in `args`: --preset NAME first wherever it
// stands, then --estimator NAME and every --set section.key=value in order. The other arguments
// are returned in order. Throws UsageError or config::ConfigError.
config::Config parse_settings_options(std::span<const std::string_view> args,
                                      std::vector<std::string_view>& rest);

// The value after option args[i]; throws UsageError when it is missing.
std::string_view option_value(std::span<const std::string_view> args, std::size_t& i);

}  // namespace raypoint::daemon
