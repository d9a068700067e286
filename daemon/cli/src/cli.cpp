#include "raypoint/cli/cli.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "config_commands.hpp"
#include "doctor_command.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/ini_file.hpp"
#include "run_command.hpp"

namespace raypoint::daemon {
namespace {

constexpr std::string_view usage = R"(usage: raypoint COMMAND [options]

commands:
  run              the daemon: webcam in, a virtual pointer out (a systemd user
                   service: systemctl --user enable --now raypoint)
      --camera DEVICE        /dev/videoN, /dev/v4l/by-id/..., or auto (default)
      --lock-exposure        lock auto exposure, gain and white balance
      --input FILE           a recorded video instead of the camera, at its own pace
      --unpaced              with --input: as fast as the core runs
      --realtime             with --input: decode the clip first, then replay it from
                             memory as a YUYV camera would deliver it (the daemon's
                             own cost, printed at exit and in ctl status)
      --duration SECONDS     stop after SECONDS (with --realtime the clip loops)
      --sink SPEC            uinput (default), file:PATH (the events as text), null
      --control PATH         control socket (default $XDG_RUNTIME_DIR/raypoint.sock)
      --no-control           no control socket
                   SIGHUP reloads the configuration; SIGINT and SIGTERM stop it,
                   releasing every button.
  ctl pause|resume|recenter|status
                   talk to the running daemon (--control PATH as for run)
  doctor           check the configuration, the webcam, /dev/uinput and the
                   service, and print the fix for each failure
  track INPUT      track a recorded video or image sequence ("frames/%04d.png"),
                   one line a frame on stdout
      --format jsonl|csv     output format (default jsonl)
      --annotate OUT.mp4     also write the video with what the tracker saw
      --fps N                frame rate for the timestamps (default: the
                             container's; 30 for an image sequence)
      --verbose              say on stderr when and why a target is lost or recovered
      --plot OUT.png         also plot x, y, z, the state and the clicks over time
  plot TRACK.jsonl -o OUT.png
                   plot track's output: x, y, z, the state band, clicks
      --events FILE          clicks from a file sink's events (run --sink file:FILE)
  preview          a window with the camera and what the tracker sees, trackbars
                   for the most-tuned settings; keys: v edges/difference, space
                   pause, w write them into the INI file, q quit. Pauses a running
                   daemon (ctl pause) while it has the camera
      --camera DEVICE | --input CLIP
      --headless             no window; with --frames N and --screenshot OUT.png
      --view edges|difference  what is drawn under the markers (key v)
  setup            guided first run: measures hand size, motion range and push
                   depth, proposes [pointer] gain, the active region and [click]
                   press_rise/release_rise, lets you try them, writes the INI on
                   yes (--headless: when the try-it clicks once a push)
      --camera DEVICE | --input CLIP | --headless | --screen-width PIXELS
  demo             render a scene in memory, track it, print the 3D positions and
                   write an annotated clip
      --scene NAME           scene preset (default nonconvex)
      --annotate OUT.mp4     annotated clip (default raypoint-demo.mp4)
  compare-estimators         measure the four estimators (docs/estimators.md)
  bench [CLIP...]  time raypoint's core (each estimator) against OpenCV's CamShift,
                   KCF, CSRT and MIL on the same decoded frames, with accuracy
                   where a CLIP has truth.jsonl and masks.npz beside it; a CLIP is
                   a video or a scene folder (default: rendered scenes)
      --peers LIST           camshift,kcf,csrt,mil (default all) or none
      --scenes LIST          rendered scenes without CLIP (default ideal,lowlight,
                             interfering,nonconvex,realworld,fast,pause)
      --frames N             at most N frames a clip
      --format table|markdown|jsonl
  print-config     print the effective configuration as an INI file (the file
                   raypoint run reads, see check-config, and the options below)
      --defaults             read no configuration file
  check-config [FILE]        check a configuration file, or the one raypoint run
                             reads ($XDG_CONFIG_HOME/raypoint/raypoint.ini, then
                             raypoint/raypoint.ini in $XDG_CONFIG_DIRS)

options for run, track, demo, compare-estimators, bench, preview, setup and
print-config:
  --config FILE              read the settings from an INI file (see print-config)
  --preset default|paper     start from the measured defaults or the paper exactly
  --estimator NAME           ray|iterative-ray|iterative-ny-ray|raster
  --set section.key=value    change one setting (repeatable; see print-config)
)";

}  // namespace

int cli_main(int argc, char** argv, const CommandSet& commands) {
    const std::vector<std::string_view> all(argv + 1, argv + argc);
    if (all.empty() || all[0] == "--help" || all[0] == "-h" || all[0] == "help") {
        std::fputs(usage.data(), all.empty() ? stderr : stdout);
        return all.empty() ? 2 : 0;
    }
    const std::string_view command = all[0];
    const std::span<const std::string_view> args(all.data() + 1, all.size() - 1);
    try {
        if (command == "run") return run_command(args, commands.recorded);
        if (command == "ctl") return ctl_command(args);
        if (command == "doctor") return doctor_command(args);
        if (command == "print-config") return print_config_command(args);
        if (command == "check-config") return check_config_command(args);
        if (commands.video_command != nullptr) {
            if (const auto code = commands.video_command(command, args)) return *code;
        }
        throw UsageError(std::string(command) + ": unknown command (see raypoint --help)");
    } catch (const UsageError& e) {
        std::fprintf(stderr, "raypoint %s: %s\n", std::string(command).c_str(), e.what());
        return 2;
    } catch (const config::InvalidConfig& e) {
        for (const auto& error : e.errors())
            std::fprintf(stderr, "raypoint %s: %s\n", std::string(command).c_str(), error.c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raypoint %s: %s\n", std::string(command).c_str(), e.what());
        return 1;
    }
}

}  // namespace raypoint::daemon
