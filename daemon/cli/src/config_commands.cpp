// SPDX-License-Identifier: MIT
#include "config_commands.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/config_paths.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/schema.hpp"
#include "raypoint/service/log.hpp"

namespace raypoint::daemon {

int print_config_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> settings;
    bool defaults = false;
    for (const std::string_view arg : args) {
        if (arg == "--defaults") {
            defaults = true;
        } else {
            settings.push_back(arg);
        }
    }
    const auto explicit_file = config_option(settings);
    if (defaults && explicit_file) throw UsageError("--defaults and --config: choose one");
    const auto file = explicit_file ? explicit_file
                      : defaults    ? std::nullopt
                                    : config::find_config_file();
    std::vector<std::string_view> rest;
    const auto config = parse_settings_options(settings, rest, file);
    if (!rest.empty()) throw UsageError(std::string(rest.front()) + ": unknown option");
    if (file) std::printf("# read from %s\n", file->c_str());
    std::fputs(config::to_ini(config).c_str(), stdout);
    return 0;
}

int check_config_command(std::span<const std::string_view> args) {
    std::optional<std::filesystem::path> file;
    for (const std::string_view arg : args) {
        if (arg.starts_with("-") && arg.size() > 1) {
            throw UsageError(std::string(arg) + ": unknown option (check-config [FILE])");
        }
        if (file) throw UsageError(std::string(arg) + ": one FILE at most");
        file = std::filesystem::path(arg);
    }
    if (!file) {
        file = config::find_config_file();
        if (!file) {
            std::string searched;
            for (const auto& candidate : config::config_search_path())
                searched += (searched.empty() ? "" : ", ") + candidate.string();
            std::printf("no configuration file (looked for %s): raypoint run uses the defaults\n",
                        searched.c_str());
            return 0;
        }
        std::printf("checking %s, the file raypoint run reads\n",
                    log::escape_control(file->string()).c_str());
    }
    try {
        config::load_config(*file);
    } catch (const config::InvalidConfig& invalid) {
        std::fflush(stdout);
        for (const auto& error : invalid.errors())
            std::fprintf(stderr, "%s\n", log::escape_control(error).c_str());
        return 1;
    }
    std::printf("%s: ok\n", log::escape_control(file->string()).c_str());
    return 0;
}

}  // namespace raypoint::daemon
