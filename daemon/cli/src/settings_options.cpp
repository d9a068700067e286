// SPDX-License-Identifier: MIT
#include "raypoint/cli/settings_options.hpp"

#include <string>

#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::daemon {
namespace {

// --preset wherever it stands: it is the base the file and the other options change.
std::optional<std::string_view> preset_option(std::span<const std::string_view> args) {
    std::optional<std::string_view> preset;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] != "--preset") continue;
        const std::string_view name = option_value(args, i);
        config::Config scratch;
        if (!config::apply_preset(scratch, name)) {
            throw UsageError("--preset " + std::string(name) + ": unknown preset (allowed: " +
                             std::string(config::preset_names) + ")");
        }
        preset = name;
    }
    return preset;
}

}  // namespace

std::string_view option_value(std::span<const std::string_view> args, std::size_t& i) {
    if (i + 1 >= args.size()) throw UsageError(std::string(args[i]) + ": missing value");
    return args[++i];
}

std::optional<std::filesystem::path> config_option(std::span<const std::string_view> args) {
    std::optional<std::filesystem::path> path;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] != "--config") continue;
        if (path) throw UsageError("--config: given twice");
        path = std::filesystem::path(option_value(args, i));
    }
    return path;
}

config::Config parse_settings_options(std::span<const std::string_view> args,
                                      std::vector<std::string_view>& rest,
                                      const std::optional<std::filesystem::path>& default_file) {
    const auto preset = preset_option(args);
    auto file_path = config_option(args);
    if (!file_path) file_path = default_file;

    config::Config config;
    if (file_path) {
        const config::IniFile file = config::read_ini_file(*file_path);
        std::vector<std::string> errors = file.errors;
        config = config::config_from_file(file, preset, errors);
        if (!errors.empty()) throw config::InvalidConfig(std::move(errors));
    } else {
        config::apply_preset(config, preset.value_or("default"));
    }

    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view option = args[i];
        if (option == "--preset" || option == "--config") {
            ++i;
        } else if (option == "--set") {
            // A wrong --set is a wrong command line, as a wrong --estimator is: exit 2.
            try {
                config::apply_assignment(config, option_value(args, i));
            } catch (const config::ConfigError& e) {
                throw UsageError(e.what());
            }
        } else if (option == "--estimator") {
            const std::string_view name = option_value(args, i);
            const config::Key* key = config::find_key("estimator", "method");
            if (key->set(config, name)) {
                throw UsageError("--estimator " + std::string(name) +
                                 ": unknown estimator (allowed: " + key->allowed() + ")");
            }
        } else {
            rest.push_back(option);
        }
    }
    auto problems = config::cross_check(config);
    if (!problems.empty()) throw config::InvalidConfig(std::move(problems));
    return config;
}

}  // namespace raypoint::daemon
