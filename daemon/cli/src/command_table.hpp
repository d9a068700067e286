// SPDX-License-Identifier: MIT
#pragma once
// Every command of raypoint and raypoint-tools, with its operands and options, in one table
// (command_table.cpp): `raypoint --help`, `raypoint COMMAND --help`, the check for unknown
// options (with a suggestion), the shell completions (which read the help) and the test that
// raypoint(1) names every option all come from it. A new command adds one row there and one
// dispatch line (cli.cpp, or the video commands' callback in raypoint-tools).

#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace raypoint::daemon {

struct OptionSpec {
    std::string_view name;   // "--format"
    std::string_view value;  // "jsonl|csv", or empty for a flag
    std::string_view help;   // lines separated by '\n'
};

struct CommandSpec {
    std::string_view name;      // "track"
    std::string_view operands;  // "INPUT", "[FILE]", or empty
    std::string_view summary;   // lines separated by '\n'
    std::span<const OptionSpec> options;
    bool settings = false;  // takes --config, --preset, --estimator and --set
};

std::span<const CommandSpec> command_table();
const CommandSpec* find_command(std::string_view name);

// `raypoint --help`: every command with its options.
void print_usage(std::FILE* out);
// `raypoint COMMAND --help`.
void print_command_help(const CommandSpec& command, std::FILE* out);

// The arguments with every `--option=value` split in two (before a `--` only). Throws UsageError
// for `--flag=value`, an unknown option (suggesting the closest one) or a missing value.
std::vector<std::string> normalize_options(const CommandSpec& command,
                                           std::span<const std::string_view> args);

// The closest of `candidates` to `wanted`, when close enough to be a misspelling of it
// (an edit distance of at most a third of its length, and at most 3); empty otherwise.
std::string_view closest_name(std::string_view wanted,
                              std::span<const std::string_view> candidates);

}  // namespace raypoint::daemon
