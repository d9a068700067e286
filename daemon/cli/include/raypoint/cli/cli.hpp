// SPDX-License-Identifier: MIT
#pragma once
// The command line shared by the two executables: `raypoint` (the service binary: run, ctl,
// doctor, print-config, check-config) and raypoint-tools (all of those plus the commands that
// read or write video files). Usage text, dispatch and the one-line error reports live here once.

#include <cstdio>
#include <optional>
#include <span>
#include <string_view>

#include "raypoint/cli/recorded_input.hpp"

namespace raypoint::daemon {

struct CommandSet {
    // The video commands (track, demo, compare-estimators, bench): the exit code, or nothing
    // when `command` is not one of them. nullptr in the service binary.
    std::optional<int> (*video_command)(std::string_view command,
                                        std::span<const std::string_view> args) = nullptr;
    RecordedSourceFactory recorded = nullptr;  // for `run --input`
};

// "raypoint VERSION (git DESCRIBE)": the project's version and `git describe` when configured.
void print_version(std::FILE* out);

// Runs the command argv names and returns the process's exit code: 0, 1 (bad input or
// settings, one line on stderr a problem) or 2 (usage).
int cli_main(int argc, char** argv, const CommandSet& commands);

}  // namespace raypoint::daemon
