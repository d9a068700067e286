// SPDX-License-Identifier: MIT
#include "raypoint/config/config_paths.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <string_view>

namespace raypoint::config {
namespace {

const std::filesystem::path file_in_dir = std::filesystem::path("raypoint") / "raypoint.ini";

// The variable's value when it is an absolute path; the specification says to ignore others.
std::optional<std::filesystem::path> absolute_env(const char* variable) {
    const char* value = std::getenv(variable);
    if (value == nullptr || value[0] != '/') return std::nullopt;
    return std::filesystem::path(value);
}

}  // namespace

std::vector<std::filesystem::path> config_search_path() {
    std::vector<std::filesystem::path> candidates;
    if (const auto home_config = absolute_env("XDG_CONFIG_HOME")) {
        candidates.push_back(*home_config / file_in_dir);
    } else if (const auto home = absolute_env("HOME")) {
        candidates.push_back(*home / ".config" / file_in_dir);
    }
    const char* dirs = std::getenv("XDG_CONFIG_DIRS");
    std::string_view rest = dirs != nullptr && dirs[0] != '\0' ? dirs : "/etc/xdg";
    while (!rest.empty()) {
        const auto colon = rest.find(':');
        const std::string_view dir = rest.substr(0, colon);
        if (dir.starts_with('/')) candidates.push_back(std::filesystem::path(dir) / file_in_dir);
        rest = colon == std::string_view::npos ? std::string_view() : rest.substr(colon + 1);
    }
    return candidates;
}

std::optional<std::filesystem::path> find_config_file() {
    for (const auto& candidate : config_search_path()) {
        struct stat info {};
        if (::stat(candidate.c_str(), &info) == 0 || (errno != ENOENT && errno != ENOTDIR)) {
            return candidate;
        }
    }
    return std::nullopt;
}

}  // namespace raypoint::config
