// SPDX-License-Identifier: MIT
#include "track_command.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/videoio.hpp>

#include "annotator.hpp"
#include "input_error.hpp"
#include "plot_command.hpp"
#include "progress_bar.hpp"
#include "raypoint/cli/output_path.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/tracker.hpp"
#include "result_writer.hpp"
#include "video_source.hpp"

namespace raypoint::daemon {
namespace {

struct TrackOptions {
    std::string input;
    OutputFormat format = OutputFormat::jsonl;
    std::string annotate;
    std::string plot;
    double fps = 0.0;
    bool verbose = false;
};

TrackOptions parse_track_options(std::span<const std::string_view> args) {
    TrackOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (arg == "--format") {
            const std::string_view value = option_value(args, i);
            if (value == "jsonl") {
                options.format = OutputFormat::jsonl;
            } else if (value == "csv") {
                options.format = OutputFormat::csv;
            } else {
                throw UsageError("--format " + std::string(value) +
                                 ": unknown format (allowed: jsonl|csv)");
            }
        } else if (arg == "--annotate") {
            options.annotate = option_value(args, i);
        } else if (arg == "--plot") {
            options.plot = option_value(args, i);
        } else if (arg == "--verbose") {
            options.verbose = true;
        } else if (arg == "--fps") {
            const std::string value(option_value(args, i));
            char* end = nullptr;
            options.fps = std::strtod(value.c_str(), &end);
            if (end == value.c_str() || *end != '\0' ||
                !(options.fps > 0.0 && options.fps <= 1000.0)) {
                throw UsageError("--fps " + value +
                                 ": not a frame rate (allowed: more than 0, at most 1000)");
            }
        } else if (arg.starts_with("-") && arg.size() > 1) {
            throw UsageError(std::string(arg) + ": unknown option (see raypoint --help)");
        } else if (options.input.empty()) {
            options.input = arg;
        } else {
            throw UsageError(std::string(arg) + ": only one input per run");
        }
    }
    if (options.input.empty()) throw UsageError("missing INPUT (a video file or pattern)");
    if (!options.annotate.empty()) check_output_path("--annotate", options.annotate);
    return options;
}

}  // namespace

int track_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest);
    const TrackOptions options = parse_track_options(rest);

    VideoSource source(options.input, options.fps);
    core::Tracker tracker(config.core);
    ResultWriter writer(stdout, options.format);
    std::optional<cv::VideoWriter> annotated;
    ProgressBar progress(source.frame_count());
    // --plot: the track and the clicks the pointer would make (its commands go nowhere).
    view::TrackLog log;
    std::optional<core::PointerController> pointer;
    int frames = 0;
    while (auto frame = source.next()) {
        const core::FrameView view{frame->bgr.data,        frame->bgr.cols,
                                   frame->bgr.rows,        static_cast<int>(frame->bgr.step),
                                   core::PixelFormat::bgr, frame->timestamp};
        const auto start = std::chrono::steady_clock::now();
        const core::FrameResult result = tracker.process(view);
        const auto spent = std::chrono::steady_clock::now() - start;
        writer.write(result,
                     static_cast<long>(
                         std::chrono::duration_cast<std::chrono::microseconds>(spent).count()));
        if (!options.plot.empty()) {
            const double t = static_cast<double>(result.timestamp) * 1e-6;
            log.samples.push_back({t, result.state, result.has_position, result.position});
            if (!pointer) {
                pointer.emplace(
                    config.core.pointer,
                    static_cast<double>(frame->bgr.cols) / static_cast<double>(frame->bgr.rows),
                    config.core.output);
            }
            for (const auto& change : pointer->update(result).button_changes()) {
                if (change.button == core::Button::left) log.clicks.push_back({t, change.pressed});
            }
        }
        if (options.verbose && (result.lost || result.recovered || result.held)) {
            const std::string what = result.lost
                                         ? "lost: " + std::string(core::to_string(result.loss))
                                     : result.recovered ? std::string("recovered")
                                                        : std::string("held: grew too fast");
            std::fprintf(stderr, "frame %lld t=%.3f: %s\n", static_cast<long long>(result.frame),
                         static_cast<double>(result.timestamp) * 1e-6, what.c_str());
        }
        if (!options.annotate.empty()) {
            if (!annotated) {
                annotated.emplace(options.annotate, cv::VideoWriter::fourcc('m', 'p', '4', 'v'),
                                  source.fps(), frame->bgr.size());
                if (!annotated->isOpened()) {
                    throw InputError(options.annotate + ": cannot write video (check the folder)");
                }
            }
            annotate(frame->bgr, tracker, result);
            annotated->write(frame->bgr);
        }
        progress.update(++frames);
    }
    std::fflush(stdout);
    if (!options.plot.empty() && !log.samples.empty()) write_plot(log, options.plot);
    return 0;
}

}  // namespace raypoint::daemon
