// SPDX-License-Identifier: MIT
#include "raypoint/cli/cli.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "command_table.hpp"
#include "config_commands.hpp"
#include "doctor_command.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/service/log.hpp"
#include "run_command.hpp"

namespace raypoint::daemon {
namespace {

bool is_help(std::string_view arg) {
    return arg == "--help" || arg == "-h";
}

int dispatch(const CommandSpec& spec, std::span<const std::string_view> args,
             const CommandSet& commands) {
    const std::string_view command = spec.name;
    if (command == "run") return run_command(args, commands.recorded);
    if (command == "ctl") return ctl_command(args);
    if (command == "doctor") return doctor_command(args);
    if (command == "print-config") return print_config_command(args);
    if (command == "check-config") return check_config_command(args);
    if (commands.video_command != nullptr) {
        if (const auto code = commands.video_command(command, args)) return *code;
    }
    throw UsageError("this binary does not run it: run raypoint " + std::string(command));
}

}  // namespace

void print_version(std::FILE* out) {
    std::fprintf(out, "raypoint %s%s%s\n", RAYPOINT_VERSION, *RAYPOINT_GIT_DESCRIBE ? " (git " : "",
                 *RAYPOINT_GIT_DESCRIBE ? RAYPOINT_GIT_DESCRIBE ")" : "");
}

int cli_main(int argc, char** argv, const CommandSet& commands) {
    const std::vector<std::string_view> all(argv + 1, argv + argc);
    if (all.empty()) {
        print_usage(stderr);
        return 2;
    }
    if (is_help(all[0]) || all[0] == "help") {
        print_usage(stdout);
        return 0;
    }
    if (all[0] == "--version") {
        print_version(stdout);
        return 0;
    }
    const std::string_view command = all[0];
    const std::span<const std::string_view> raw(all.data() + 1, all.size() - 1);
    try {
        const CommandSpec* spec = find_command(command);
        if (spec == nullptr) {
            std::vector<std::string_view> names;
            for (const CommandSpec& known : command_table())
                names.push_back(known.name);
            const std::string_view near = closest_name(command, names);
            throw UsageError("unknown command" +
                             (near.empty() ? "" : " (did you mean " + std::string(near) + "?)") +
                             "; see raypoint --help");
        }
        // --help wins over everything else on the line, as in most programs.
        const auto options_end = std::find(raw.begin(), raw.end(), "--");
        if (std::any_of(raw.begin(), options_end, is_help)) {
            print_command_help(*spec, stdout);
            return 0;
        }
        const std::vector<std::string> normalized = normalize_options(*spec, raw);
        const std::vector<std::string_view> args(normalized.begin(), normalized.end());
        return dispatch(*spec, args, commands);
    } catch (const UsageError& e) {
        log::error("raypoint " + std::string(command) + ": " + e.what());
        return 2;
    } catch (const config::InvalidConfig& e) {
        for (const auto& error : e.errors())
            log::error("raypoint " + std::string(command) + ": " + error);
        return 1;
    } catch (const std::exception& e) {
        log::error("raypoint " + std::string(command) + ": " + e.what());
        return 1;
    }
}

}  // namespace raypoint::daemon
