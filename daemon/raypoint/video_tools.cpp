#include "video_tools.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace raypoint::daemon {

bool needs_video_tools(std::span<const std::string_view> args) {
    if (args.empty()) return false;
    constexpr std::array<std::string_view, 7> video_commands{
        "track", "demo", "compare-estimators", "bench", "plot", "preview", "setup"};
    const std::string_view command = args.front();
    if (std::find(video_commands.begin(), video_commands.end(), command) != video_commands.end()) {
        return true;
    }
    return command == "run" && std::find(args.begin(), args.end(), "--input") != args.end();
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
        tried += "\n  execv(" + path + "): " + std::strerror(errno);
    }
    std::fprintf(stderr,
                 "raypoint: %s needs raypoint-tools, which was not found:%s\n"
                 "  (reinstall raypoint, or build the raypoint-tools target)\n",
                 argv[1], tried.c_str());
    return 127;
}

}  // namespace raypoint::daemon
