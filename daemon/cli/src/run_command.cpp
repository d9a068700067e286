// SPDX-License-Identifier: MIT
#include "run_command.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "raypoint/capture/camera_errors.hpp"
#include "raypoint/capture/v4l2_camera.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/sink_option.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/config_paths.hpp"
#include "raypoint/loop/pointer_daemon.hpp"
#include "raypoint/output/pointer_events.hpp"
#include "raypoint/service/log.hpp"
#include "status_json.hpp"

namespace raypoint::daemon {
namespace {

struct RunOptions {
    std::string input;  // a recorded video instead of the camera
    bool paced = true;
    bool realtime = false;  // --input decoded up front, replayed as a YUYV camera
    bool mjpeg = false;     // --realtime-format mjpeg: replayed as an MJPEG camera
    bool format_given = false;
    std::optional<double> duration_s;
    std::optional<std::string> camera;  // overrides camera.device
    bool lock_exposure = false;         // or camera.lock_exposure
    std::string sink = "uinput";
    std::optional<std::string> control_path;
    bool no_control = false;
};

double parse_duration(std::string_view text) {
    const std::string value(text);
    char* end = nullptr;
    const double seconds = std::strtod(value.c_str(), &end);
    // Up to a year: the milliseconds stay far inside the clock's range.
    if (value.empty() || *end != '\0' || !(seconds > 0.0) || seconds > 365.0 * 86400.0) {
        throw UsageError("--duration " + value + ": needs seconds > 0, as in --duration 60");
    }
    return seconds;
}

RunOptions parse_run_options(std::span<const std::string_view> args) {
    RunOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (arg == "--input") {
            options.input = option_value(args, i);
        } else if (arg == "--unpaced") {
            options.paced = false;
        } else if (arg == "--realtime") {
            options.realtime = true;
        } else if (arg == "--realtime-format") {
            const std::string_view format = option_value(args, i);
            if (format != "yuyv" && format != "mjpeg") {
                throw UsageError("--realtime-format " + std::string(format) +
                                 ": unknown (allowed: yuyv, mjpeg)");
            }
            options.mjpeg = format == "mjpeg";
            options.format_given = true;
        } else if (arg == "--duration") {
            options.duration_s = parse_duration(option_value(args, i));
        } else if (arg == "--camera") {
            options.camera = option_value(args, i);
        } else if (arg == "--lock-exposure") {
            options.lock_exposure = true;
        } else if (arg == "--sink") {
            options.sink = option_value(args, i);
        } else if (arg == "--control") {
            options.control_path = std::string(option_value(args, i));
        } else if (arg == "--no-control") {
            options.no_control = true;
        } else {
            throw UsageError(std::string(arg) + ": unknown option (see raypoint --help)");
        }
    }
    if (options.realtime && options.input.empty()) {
        throw UsageError("--realtime replays a clip: it needs --input CLIP");
    }
    if (options.format_given && !options.realtime) {
        throw UsageError("--realtime-format is the replayed camera's format: it needs --realtime");
    }
    if (options.realtime && !options.paced) {
        throw UsageError("--realtime and --unpaced contradict each other: choose one");
    }
    return options;
}

}  // namespace

int run_command(std::span<const std::string_view> args, RecordedSourceFactory recorded) {
    block_daemon_signals();
    // SIGHUP re-reads the same file and re-applies the same command line over it.
    const std::vector<std::string> kept(args.begin(), args.end());
    const auto build_config = [kept] {
        const std::vector<std::string_view> views(kept.begin(), kept.end());
        std::vector<std::string_view> ignored;
        return parse_settings_options(views, ignored, config::find_config_file());
    };
    std::vector<std::string_view> rest;
    DaemonParts parts;
    parts.config = parse_settings_options(args, rest, config::find_config_file());
    parts.reload = build_config;
    const RunOptions options = parse_run_options(rest);

    const auto& preprocess = parts.config.core.preprocess;
    if (options.duration_s) {
        parts.duration = std::chrono::milliseconds(std::llround(*options.duration_s * 1000.0));
    }
    if (!options.input.empty()) {
        if (recorded == nullptr) {
            throw UsageError("--input: this binary reads no video files; run it as raypoint-tools");
        }
        // With --duration a --realtime clip loops to fill it; without, it plays once.
        // An MJPEG replay is decoded to the size the camera path would ask for.
        CameraOptions camera;
        camera.settings = parts.config.camera;
        camera.working = cv::Size(preprocess.work_width, preprocess.work_height);
        parts.source =
            recorded({options.input, options.paced, options.realtime,
                      options.duration_s.has_value(), options.mjpeg, camera.capture_least()});
        parts.exit_when_lost = true;
    } else {
        CameraOptions camera;
        camera.settings = parts.config.camera;
        if (options.camera) camera.settings.device = *options.camera;
        if (options.lock_exposure) camera.settings.lock_exposure = true;
        camera.working = cv::Size(preprocess.work_width, preprocess.work_height);
        try {
            parts.source = std::make_unique<V4l2Camera>(camera);
        } catch (const CameraError& e) {
            // No camera yet (unplugged, or its permissions not granted yet): the service starts
            // and waits for one rather than failing into a restart loop. The reason stays in the
            // log, in STATUS= and in `ctl status`.
            log::warning(std::string("waiting for a camera: ") + e.what());
            auto closed = std::make_unique<V4l2Camera>(camera, V4l2Camera::StartClosed{});
            closed->reopen();  // records last_error() for the status line; fails as above
            parts.source = std::move(closed);
            parts.start_closed = true;
        }
        parts.close_when_paused = true;
    }
    parts.sink =
        make_sink(parse_sink_spec(options.sink), device_profile(parts.config.core.pointer.motion));
    if (!options.no_control) {
        try {
            parts.control = std::make_unique<ControlServer>(
                options.control_path ? *options.control_path : default_control_path());
        } catch (const ControlError& e) {
            // The pointer works without remote control; say why there is none.
            log::warning(std::string("no control socket: ") + e.what());
        }
    }
    PointerDaemon daemon(std::move(parts));
    return daemon.run();
}

int ctl_command(std::span<const std::string_view> args) {
    std::optional<ControlCommand> command;
    std::optional<std::string> path;
    bool json = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--control") {
            path = std::string(option_value(args, i));
        } else if (args[i] == "--json") {
            json = true;
        } else if (const auto parsed = control_command_from_string(args[i]); parsed && !command) {
            command = parsed;
        } else {
            throw UsageError(std::string(args[i]) +
                             ": unknown (usage: raypoint ctl pause|resume|toggle|recenter|status)");
        }
    }
    if (!command) throw UsageError("usage: raypoint ctl pause|resume|toggle|recenter|status");
    if (json && *command != ControlCommand::status) throw UsageError("--json: only for status");
    const std::string reply = send_control(path ? *path : default_control_path(), *command);
    const bool failed = reply.rfind("error:", 0) == 0;
    std::fputs(json && !failed ? status_json(reply).c_str() : reply.c_str(), stdout);
    return failed ? 1 : 0;
}

}  // namespace raypoint::daemon
