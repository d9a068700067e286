// SPDX-License-Identifier: MIT
#include "plot_command.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "input_error.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/view/plot.hpp"

namespace raypoint::daemon {

void write_png(const cv::Mat& picture, const std::string& path) {
    bool written = false;
    try {
        // The format by the name's extension; JPEG at 80 keeps a screenshot to a few tens of kB.
        written = !picture.empty() &&
                  cv::imwrite(path, picture,
                              {cv::IMWRITE_PNG_COMPRESSION, 9, cv::IMWRITE_JPEG_QUALITY, 80});
    } catch (const cv::Exception&) {
        written = false;
    }
    if (!written) throw InputError(path + ": cannot write the picture (check the folder and .png)");
}

void write_plot(const view::TrackLog& log, const std::string& path) {
    write_png(view::draw_plot(log, view::plot_layout(log)), path);
}

int plot_command(std::span<const std::string_view> args) {
    std::string input;
    std::string output;
    std::string events;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-o" || args[i] == "--output") {
            output = option_value(args, i);
        } else if (args[i] == "--events") {
            events = option_value(args, i);
        } else if (args[i].starts_with("-") && args[i].size() > 1) {
            throw UsageError(std::string(args[i]) + ": unknown option (see raypoint --help)");
        } else if (input.empty()) {
            input = args[i];
        } else {
            throw UsageError(std::string(args[i]) + ": only one TRACK.jsonl");
        }
    }
    if (input.empty()) throw UsageError("missing TRACK.jsonl (raypoint track's output)");
    if (output.empty()) throw UsageError("missing -o OUT.png");
    view::TrackLog log;
    try {
        log = view::read_track_jsonl(input);
        if (!events.empty()) {
            const auto clicks = view::read_sink_clicks(events);
            log.clicks.insert(log.clicks.end(), clicks.begin(), clicks.end());
            std::stable_sort(log.clicks.begin(), log.clicks.end(),
                             [](const auto& a, const auto& b) { return a.t < b.t; });
        }
    } catch (const view::TrackLogError& e) {
        throw InputError(e.what());
    }
    write_plot(log, output);
    return 0;
}

}  // namespace raypoint::daemon
