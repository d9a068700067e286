// raypoint: a webcam 3D pointer. The command line: offline tracking, the demo, the settings.

#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "compare_command.hpp"
#include "demo_command.hpp"
#include "errors.hpp"
#include "raypoint/config/schema.hpp"
#include "settings_options.hpp"
#include "track_command.hpp"

namespace {

constexpr std::string_view usage = R"(usage: raypoint COMMAND [options]

commands:
  track INPUT      track a recorded video or image sequence ("frames/%04d.png"),
                   one line a frame on stdout
      --format jsonl|csv     output format (default jsonl)
      --annotate OUT.mp4     also write the video with what the tracker saw
      --fps N                frame rate for the timestamps (default: the
                             container's; 30 for an image sequence)
      --verbose              say on stderr when and why a target is lost or recovered
  demo             render a scene in memory, track it, print the 3D positions and
                   write an annotated clip
      --scene NAME           scene preset (default nonconvex)
      --annotate OUT.mp4     annotated clip (default raypoint-demo.mp4)
  compare-estimators         measure the four estimators (docs/estimators.md)
  print-config     print the effective configuration as an INI file

options for track, demo and print-config:
  --preset default|paper     start from the measured defaults or the paper exactly
  --estimator NAME           ray|iterative-ray|iterative-ny-ray|raster
  --set section.key=value    change one setting (repeatable; see print-config)
)";

int print_config(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const auto config = raypoint::daemon::parse_settings_options(args, rest);
    if (!rest.empty()) {
        throw raypoint::daemon::UsageError(std::string(rest.front()) + ": unknown option");
    }
    std::fputs(raypoint::config::to_ini(config).c_str(), stdout);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string_view> all(argv + 1, argv + argc);
    if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
        std::fputs(usage.data(), all.empty() ? stderr : stdout);
        return all.empty() ? 2 : 0;
    }
    const std::string_view command = all[0];
    const std::span<const std::string_view> args(all.data() + 1, all.size() - 1);
    try {
        if (command == "track") return raypoint::daemon::track_command(args);
        if (command == "demo") return raypoint::daemon::demo_command(args);
        if (command == "compare-estimators") return raypoint::daemon::compare_command(args);
        if (command == "print-config") return print_config(args);
        throw raypoint::daemon::UsageError(std::string(command) +
                                           ": unknown command (see raypoint --help)");
    } catch (const raypoint::daemon::UsageError& e) {
        std::fprintf(stderr, "raypoint %s: %s\n", std::string(command).c_str(), e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raypoint %s: %s\n", std::string(command).c_str(), e.what());
        return 1;
    }
}
