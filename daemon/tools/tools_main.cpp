// SPDX-License-Identifier: MIT
// raypoint-tools: every raypoint command, including those that read and write video files
// (track, demo, compare-estimators, bench, run --input, plot) or open a window (preview, setup).
// `raypoint` runs it for them (video_tools.hpp); it is installed in libexec, not on $PATH.

#include "bench_command.hpp"
#include "compare_command.hpp"
#include "demo_command.hpp"
#include "eval_clicks_command.hpp"
#include "plot_command.hpp"
#include "preview_command.hpp"
#include "raypoint/cli/cli.hpp"
#include "recorded_source.hpp"
#include "setup_command.hpp"
#include "track_command.hpp"

namespace {

std::optional<int> video_command(std::string_view command, std::span<const std::string_view> args) {
    using namespace raypoint::daemon;
    if (command == "track") return track_command(args);
    if (command == "demo") return demo_command(args);
    if (command == "compare-estimators") return compare_command(args);
    if (command == "bench") return bench_command(args);
    if (command == "plot") return plot_command(args);
    if (command == "preview") return preview_command(args);
    if (command == "setup") return setup_command(args);
    if (command == "eval-clicks") return eval_clicks_command(args);
    return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
    return raypoint::daemon::cli_main(argc, argv,
                                      {video_command, raypoint::daemon::make_recorded_source});
}
