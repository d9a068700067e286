// SPDX-License-Identifier: MIT
#include "preview_input.hpp"

#include <cstdio>
#include <cstdlib>

#include "raypoint/capture/camera_errors.hpp"
#include "raypoint/capture/v4l2_camera.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/config_paths.hpp"
#include "raypoint/control/control_socket.hpp"
#include "recorded_source.hpp"

namespace raypoint::daemon {

bool parse_preview_input_option(std::span<const std::string_view> args, std::size_t& i,
                                PreviewInputOptions& options) {
    if (args[i] == "--input") {
        options.clip = option_value(args, i);
    } else if (args[i] == "--camera") {
        options.camera = std::string(option_value(args, i));
    } else if (args[i] == "--control") {
        options.control = std::string(option_value(args, i));
    } else if (args[i] == "--no-control") {
        options.use_control = false;
    } else {
        return false;
    }
    if (!options.clip.empty() && options.camera) {
        throw UsageError("--input and --camera: one source at a time");
    }
    return true;
}

bool parse_preview_loop_option(std::span<const std::string_view> args, std::size_t& i,
                               PreviewLoopOptions& options) {
    if (args[i] == "--headless") {
        options.headless = true;
    } else if (args[i] == "--frames") {
        const std::string text(option_value(args, i));
        char* end = nullptr;
        const long frames = std::strtol(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0' || frames < 1 || frames > 100'000'000) {
            throw UsageError("--frames " + text + ": not a frame count (allowed: 1..100000000)");
        }
        options.frames = static_cast<int>(frames);
    } else if (args[i] == "--screenshot") {
        options.screenshot = option_value(args, i);
    } else if (args[i] == "--view") {
        const std::string_view value = option_value(args, i);
        if (value == "edges") {
            options.view = view::BackgroundView::edges;
        } else if (value == "difference") {
            options.view = view::BackgroundView::difference;
        } else {
            throw UsageError("--view " + std::string(value) +
                             ": unknown view (allowed: edges|difference)");
        }
    } else {
        return false;
    }
    return true;
}

std::optional<std::filesystem::path> user_config_file() {
    return config::find_config_file();
}

std::filesystem::path ini_to_write(std::span<const std::string_view> args) {
    if (auto named = config_option(args)) return *named;
    if (auto found = config::find_config_file()) return *found;
    const auto candidates = config::config_search_path();
    if (candidates.empty()) {
        throw UsageError("no place for raypoint.ini: set HOME or XDG_CONFIG_HOME, or --config");
    }
    return candidates.front();
}

PreviewInput::PreviewInput(const PreviewInputOptions& options, const config::Config& config,
                           bool unpaced) {
    if (!options.clip.empty()) {
        source_ = make_recorded_source({options.clip, !unpaced, false, false, false, {}});
        return;
    }
    if (options.use_control) {
        // No daemon (no socket, nobody answering) is the usual case, not an error.
        try {
            const std::string path = options.control ? *options.control : default_control_path();
            if (send_control(path, ControlCommand::pause).starts_with("paused")) {
                paused_daemon_ = path;
                std::fprintf(stderr, "raypoint preview: paused the running daemon (%s)\n",
                             path.c_str());
            }
        } catch (const std::exception&) {
        }
    }
    CameraOptions camera;
    camera.settings = config.camera;
    if (options.camera) camera.settings.device = *options.camera;
    camera.working = {config.core.preprocess.work_width, config.core.preprocess.work_height};
    try {
        source_ = std::make_unique<V4l2Camera>(camera);
    } catch (const CameraError& e) {
        if (!paused_daemon_) throw;
        resume_daemon();
        throw CameraError(std::string(e.what()) +
                          "; the paused daemon still holds the camera: stop it "
                          "(systemctl --user stop raypoint) for the preview, start it after");
    } catch (...) {
        resume_daemon();
        throw;
    }
}

void PreviewInput::resume_daemon() noexcept {
    if (!paused_daemon_) return;
    try {
        send_control(*paused_daemon_, ControlCommand::resume);
        std::fprintf(stderr, "raypoint preview: resumed the daemon\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raypoint preview: could not resume the daemon: %s\n", e.what());
    }
    paused_daemon_.reset();
}

PreviewInput::~PreviewInput() {
    source_.reset();
    resume_daemon();
}

}  // namespace raypoint::daemon
