// SPDX-License-Identifier: MIT
// raypoint: a webcam 3D pointer. The service binary: the daemon and its control, configuration
// and diagnosis commands. Commands that read video files run in raypoint-tools, so that the
// service does not map OpenCV's video stack (recorded_source.hpp).

#include <string_view>
#include <vector>

#include "raypoint/cli/cli.hpp"
#include "video_tools.hpp"

int main(int argc, char** argv) {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    if (raypoint::daemon::needs_video_tools(args)) return raypoint::daemon::exec_video_tools(argv);
    return raypoint::daemon::cli_main(argc, argv, {});
}
