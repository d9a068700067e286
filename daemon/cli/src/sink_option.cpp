// SPDX-License-Identifier: MIT
#include "raypoint/cli/sink_option.hpp"

#include <string>

#include "raypoint/cli/usage_error.hpp"

namespace raypoint::daemon {

namespace {

constexpr std::string_view file_prefix = "file:";
constexpr std::string_view allowed = "uinput, file:PATH or null";

}  // namespace

SinkSpec parse_sink_spec(std::string_view value) {
    if (value.empty()) throw UsageError("--sink needs a value: " + std::string(allowed));
    if (value == "uinput") return SinkSpec{SinkKind::uinput, {}};
    if (value == "null") return SinkSpec{SinkKind::null, {}};
    if (value.starts_with(file_prefix)) {
        const std::string_view path = value.substr(file_prefix.size());
        if (path.empty()) {
            throw UsageError("--sink file: needs a path, as in --sink file:events.txt");
        }
        return SinkSpec{SinkKind::file, std::filesystem::path(path)};
    }
    throw UsageError("--sink " + std::string(value) + ": unknown sink; use " +
                     std::string(allowed));
}

}  // namespace raypoint::daemon
