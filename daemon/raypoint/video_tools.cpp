// SPDX-License-Identifier: MIT
#include "video_tools.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "raypoint/service/log.hpp"

namespace raypoint::daemon {

bool needs_video_tools(std::span<const std::string_view> args) {
    if (args.empty()) return false;
    constexpr std::array<std::string_view, 8> video_commands{
        "track", "demo", "compare-estimators", "bench", "eval-clicks", "plot", "preview", "setup"};
    // Help comes from the command table, which this binary holds too (raypoint-tools may be
    // missing: the help still says what the command would do).
    const auto options_end = std::find(args.begin(), args.end(), "--");
    if (std::any_of(args.begin(), options_end,
                    [](std::string_view arg) { return arg == "--help" || arg == "-h"; })) {
        return false;
    }
    const std::string_view command = args.front();
    if (std::find(video_commands.begin(), video_commands.end(), command) != video_commands.end()) {
        return true;
    }
    return command == "run" && std::any_of(args.begin(), options_end, [](std::string_view arg) {
               return arg == "--input" || arg.starts_with("--input=");
           });
}

int exec_video_tools(char** argv) {
    std::string beside;
    std::array<char, 4096> self{};
    const ssize_t length = readlink("/proc/self/exe", self.data(), self.size() - 1);
    if (length > 0) {
        beside.assign(self.data(), static_cast<std::size_t>(length));
        beside = beside.substr(0, beside.rfind('/') + 1) + "raypoint-tools";
    }
    std::string tried;
    for (const std::string& path : {beside, std::string(RAYPOINT_LIBEXEC_DIR "/raypoint-tools")}) {
        if (path.empty()) continue;
        execv(path.c_str(), argv);
        tried += "; execv(" + path + "): " + std::strerror(errno);
    }
    // One line, at err: under systemd the journal records why `run --input` did not start.
    log::error(std::string("raypoint: ") + argv[1] +
               " needs raypoint-tools, which was not found (" +
               tried.substr(tried.empty() ? 0 : 2) +
               "): install the raypoint-tools package, or build the raypoint-tools target");
    return 127;
}

}  // namespace raypoint::daemon
