// SPDX-License-Identifier: MIT
#pragma once
// Where preview and setup get frames: a recorded clip (--input), or the camera (--camera, else
// the configured [camera] device). Opening the camera while `raypoint run` is running first
// asks that daemon to pause over its control socket, and resumes it when the preview ends: the
// service must not click while the user tunes, and the two must not fight over the device.

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "preview_window.hpp"
#include "raypoint/capture/frame_source.hpp"
#include "raypoint/config/config.hpp"

namespace raypoint::daemon {

struct PreviewInputOptions {
    std::string clip;                    // --input
    std::optional<std::string> camera;   // --camera
    std::optional<std::string> control;  // --control PATH
    bool use_control = true;             // --no-control: never talk to a daemon
};

// --input, --camera, --control, --no-control at args[i] (i moves past a value); false when
// args[i] is none of them.
bool parse_preview_input_option(std::span<const std::string_view> args, std::size_t& i,
                                PreviewInputOptions& options);
// --headless, --frames N, --screenshot FILE, --view edges|difference.
bool parse_preview_loop_option(std::span<const std::string_view> args, std::size_t& i,
                               PreviewLoopOptions& options);

// The configuration `raypoint run` reads when no --config is given.
std::optional<std::filesystem::path> user_config_file();
// The file the save key writes: --config FILE, else the one `raypoint run` reads, else
// $XDG_CONFIG_HOME/raypoint/raypoint.ini (created).
std::filesystem::path ini_to_write(std::span<const std::string_view> args);

class PreviewInput {
  public:
    // Throws InputError or CameraError naming the clip or the device. A clip plays at its own
    // rate unless `unpaced` (headless runs go as fast as they can).
    PreviewInput(const PreviewInputOptions& options, const config::Config& config, bool unpaced);
    ~PreviewInput();  // resumes the daemon it paused
    PreviewInput(const PreviewInput&) = delete;
    PreviewInput& operator=(const PreviewInput&) = delete;

    FrameSource& frames() { return *source_; }

  private:
    void resume_daemon() noexcept;

    std::unique_ptr<FrameSource> source_;
    std::optional<std::string> paused_daemon_;  // its control socket
};

}  // namespace raypoint::daemon
