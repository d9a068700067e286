// SPDX-License-Identifier: MIT
// A configuration file from disk to a valid Config: read (bounded), parse, preset, values,
// cross-checks. Every error is collected before anything is thrown.

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "raypoint/config/ini_file.hpp"

namespace raypoint::config {
namespace {

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) {
        if (!text.empty()) text += '\n';
        text += line;
    }
    return text;
}

struct FileCloser {
    void operator()(std::FILE* file) const noexcept { std::fclose(file); }
};

}  // namespace

InvalidConfig::InvalidConfig(std::vector<std::string> errors)
    : ConfigError(joined(errors)), errors_(std::move(errors)) {}

IniFile read_ini_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw InvalidConfig({name + ": cannot open: " + std::strerror(errno)});
    // Read one byte past the limit to tell "exactly at the limit" from "over it", and never more:
    // /dev/zero or a huge log must not be read to its end.
    std::string text;
    char chunk[65536];
    while (text.size() <= max_file_bytes) {
        const std::size_t wanted = std::min(sizeof chunk, max_file_bytes + 1 - text.size());
        const std::size_t got = std::fread(chunk, 1, wanted, file.get());
        if (got == 0) break;
        text.append(chunk, got);
    }
    if (std::ferror(file.get())) {
        throw InvalidConfig({name + ": cannot read: " + std::strerror(errno)});
    }
    if (text.size() > max_file_bytes) {
        throw InvalidConfig({name + ": larger than " + std::to_string(max_file_bytes >> 20) +
                             " MiB, which no raypoint configuration is"});
    }
    return parse_ini(text, name);
}

Config config_from_file(const IniFile& file, std::optional<std::string_view> preset,
                        std::vector<std::string>& errors) {
    Config config;
    const std::string_view name = preset        ? *preset
                                  : file.preset ? std::string_view(*file.preset)
                                                : std::string_view("default");
    if (!apply_preset(config, name)) {
        errors.push_back(file.name + ": unknown preset " + std::string(name) +
                         " (allowed: " + std::string(preset_names) + ")");
    }
    // parse_ini read and checked every value; what is left cannot fail.
    for (const IniSetting& setting : file.settings)
        setting.key->assign(config, setting.value);
    return config;
}

namespace {

// "file:line: problem" for a cross-check's problem: the line is the last in the file of the keys
// the problem names (the one that made the pair wrong, as a reader edits top down); without one
// (both values from the preset), "file: problem".
std::string located(const IniFile& file, const std::string& problem) {
    int line = 0;
    for (const IniSetting& setting : file.settings) {
        const std::string name = setting.key->full_name();
        for (std::size_t at = problem.find(name); at != std::string::npos;
             at = problem.find(name, at + 1)) {
            const std::size_t end = at + name.size();
            const auto part_of_name = [](char c) {
                return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
            };
            if ((at == 0 || !part_of_name(problem[at - 1])) &&
                (end == problem.size() || !part_of_name(problem[end]))) {
                line = std::max(line, setting.line);
                break;
            }
        }
    }
    std::string out = file.name;
    if (line > 0) out.append(":").append(std::to_string(line));
    return out.append(": ").append(problem);
}

}  // namespace

Config load_config(const std::filesystem::path& path, std::optional<std::string_view> preset) {
    const IniFile file = read_ini_file(path);
    std::vector<std::string> errors = file.errors;
    Config config = config_from_file(file, preset, errors);
    // Cross-checks of a half-applied file would blame keys that are fine.
    if (errors.empty()) {
        for (const auto& problem : cross_check(config))
            errors.push_back(located(file, problem));
    }
    if (!errors.empty()) throw InvalidConfig(std::move(errors));
    return config;
}

}  // namespace raypoint::config
