// SPDX-License-Identifier: MIT
#pragma once
// The preview's loop, shared by `raypoint preview` and `raypoint setup`'s try-it step: frames
// from a FrameSource through a PreviewSession, shown in an OpenCV highgui window with
// trackbars for the settings people tune most, or, headless, only rendered (for a screenshot).

#include <filesystem>
#include <optional>
#include <string>

#include "raypoint/capture/frame_source.hpp"
#include "raypoint/config/schema.hpp"
#include "raypoint/view/preview_session.hpp"

namespace raypoint::daemon {

// A setting on a trackbar: the bar's position is value x scale, 0..max (trackbars are ints).
struct Tunable {
    std::string_view section;
    std::string_view name;
    const char* label;
    double scale;
    int max;
};

// Edge threshold, search and idle thresholds, the area window (min and max area), press rise.
std::span<const Tunable> tunables();
// Their schema keys, for writing them into an INI file.
std::vector<const config::Key*> tunable_keys();

struct PreviewLoopOptions {
    bool headless = false;
    std::optional<int> frames;  // stop after this many frames
    std::string screenshot;     // the last picture (PNG, or JPEG by its name), at the end
    view::BackgroundView view = view::BackgroundView::edges;
    std::filesystem::path ini;  // the file the save key writes
    std::string title = "raypoint preview";
};

// Runs until the input ends, `frames` frames, q or Esc, or SIGINT/SIGTERM. Keys: v switches
// edges/difference, space pauses, w writes the tunables into `ini`, q quits. Throws InputError
// when the camera is lost or the screenshot cannot be written. Returns the frames processed.
int run_preview_loop(FrameSource& source, view::PreviewSession& session,
                     const PreviewLoopOptions& options);

}  // namespace raypoint::daemon
