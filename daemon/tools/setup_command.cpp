// SPDX-License-Identifier: MIT
#include "setup_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <opencv2/highgui.hpp>
#include <opencv2/imgproc.hpp>

#include "input_error.hpp"
#include "preview_input.hpp"
#include "preview_window.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/ini_update.hpp"
#include "raypoint/view/setup_measure.hpp"

namespace raypoint::daemon {
namespace {

// The guide, by seconds since the target was first tracked. The measurements use every tracked
// frame whatever the step (a recorded run need not follow the prompts).
const char* prompt(double seconds_tracked, bool tracked) {
    if (!tracked) return "Wave your hand in front of the camera";
    if (seconds_tracked < 3.0) return "Hold your hand still";
    if (seconds_tracked < 9.0) return "Move your hand across the whole view, slowly";
    if (seconds_tracked < 16.0) return "Push toward the camera three times, as a click";
    return "Done: press any key";
}
constexpr double guide_seconds = 16.0;

void draw_prompt(cv::Mat& picture, const char* text) {
    cv::rectangle(picture, {0, 0}, {picture.cols - 1, 36}, cv::Scalar(0, 0, 0), cv::FILLED);
    cv::putText(picture, text, {10, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.7, cv::Scalar(255, 255, 255),
                2, cv::LINE_AA);
}

const std::vector<const config::Key*>& proposed_keys() {
    static const std::vector<const config::Key*> keys{
        config::find_key("pointer", "gain"),          config::find_key("pointer", "active_left"),
        config::find_key("pointer", "active_right"),  config::find_key("pointer", "active_top"),
        config::find_key("pointer", "active_bottom"), config::find_key("click", "press_rise"),
        config::find_key("click", "release_rise")};
    return keys;
}

// Runs the source through a session, measuring; with a window, shows the guide's prompts.
void measure(FrameSource& source, view::PreviewSession& session, view::SetupMeasure& measured,
             const PreviewLoopOptions& options) {
    std::optional<core::Timestamp> first_tracked;
    int frames = 0;
    while (!(options.frames && frames >= *options.frames)) {
        const Capture capture = source.next(1000);
        if (capture.status == CaptureStatus::ended) break;
        if (capture.status == CaptureStatus::lost)
            throw InputError("camera lost: " + capture.reason);
        if (capture.status != CaptureStatus::frame) continue;
        session.process(capture.frame);
        ++frames;
        const core::FrameResult& result = session.last_result();
        measured.add(result);
        if (!first_tracked && result.state == core::TrackerState::tracking) {
            first_tracked = result.timestamp;
        }
        const double seconds =
            first_tracked ? static_cast<double>(result.timestamp - *first_tracked) * 1e-6 : 0.0;
        if (options.headless) continue;
        cv::Mat picture = session.render();
        draw_prompt(picture, prompt(seconds, first_tracked.has_value()));
        cv::imshow(options.title, picture);
        const int key = cv::waitKey(1);
        if (seconds >= guide_seconds && key >= 0) break;
        if ((key & 0xff) == 'q' || (key & 0xff) == 27) throw UsageError("setup cancelled");
    }
}

// The proposal through the pointer once more on a second pass of a clip: the presses it makes.
void print_proposal(const view::SetupProposal& p) {
    const view::SetupFigures& f = p.figures;
    std::printf(
        "measured: %d tracked frames; hand %.4f of the frame; centroid range x %.2f..%.2f,"
        " y %.2f..%.2f; %zu pushes, depth %.3f (rise of sqrt(area))\n",
        f.tracked_frames, f.hand_area, f.left, f.right, f.top, f.bottom, f.push_rises.size(),
        f.push_depth);
    std::printf("proposed:\n");
    for (const config::Key* key : proposed_keys()) {
        std::printf("  [%s] %s = %s\n", std::string(key->section).c_str(),
                    std::string(key->name).c_str(), key->format(p.config).c_str());
    }
}

}  // namespace

int setup_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config start = parse_settings_options(args, rest, user_config_file());
    PreviewInputOptions input;
    PreviewLoopOptions loop;
    loop.title = "raypoint setup";
    int screen_width = 1920;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (parse_preview_input_option(rest, i, input)) continue;
        if (parse_preview_loop_option(rest, i, loop)) continue;
        if (rest[i] == "--screen-width") {
            const std::string text(option_value(rest, i));
            screen_width = std::atoi(text.c_str());
            if (screen_width < 320 || screen_width > 16384) {
                throw UsageError("--screen-width " + text + ": not a width (allowed: 320..16384)");
            }
        } else {
            throw UsageError(std::string(rest[i]) + ": unknown option (see raypoint --help)");
        }
    }
    const std::filesystem::path ini = ini_to_write(args);
    // One camera (and one pause of a running daemon) for both steps; a clip is opened again
    // for the try-it, from its start.
    auto source = std::make_unique<PreviewInput>(input, start, loop.headless);
    std::optional<view::SetupProposal> proposal;
    {
        view::PreviewSession session(start);
        view::SetupMeasure measured;
        measure(source->frames(), session, measured, loop);
        proposal = measured.propose(start, screen_width);
        if (!proposal) {
            throw InputError("the hand was tracked for " +
                             std::to_string(measured.figures().tracked_frames) +
                             " frames, too few to measure: move it in good light and try again");
        }
    }
    print_proposal(*proposal);

    // Try it: the proposal on the input again (a clip from its start, or the live camera).
    if (!input.clip.empty()) {
        source.reset();
        source = std::make_unique<PreviewInput>(input, proposal->config, loop.headless);
    }
    view::PreviewSession trial(proposal->config);
    PreviewLoopOptions try_loop = loop;
    try_loop.title = "raypoint setup: try it (q when done)";
    try_loop.ini = ini;
    if (!loop.headless) std::printf("try it: push to click; q closes the window\n");
    run_preview_loop(source->frames(), trial, try_loop);
    const std::size_t pushes = proposal->figures.push_rises.size();
    std::printf("try it: %d clicks (%zu pushes measured)\n", trial.presses(), pushes);

    bool accept = false;
    if (loop.headless) {
        // Nobody to ask: accepted when the proposal clicks on each measured push, and only then.
        accept = pushes > 0 && trial.presses() == static_cast<int>(pushes);
        if (!accept) std::printf("not written: the proposal did not click once a push\n");
    } else {
        std::printf("write these settings to %s? [y/N] ", ini.c_str());
        std::fflush(stdout);
        std::string answer;
        std::getline(std::cin, answer);
        accept = answer == "y" || answer == "Y" || answer == "yes";
    }
    if (!accept) return 1;
    config::write_ini_values(ini, proposal->config, proposed_keys());
    std::printf("wrote %zu settings to %s\n", proposed_keys().size(), ini.c_str());
    return 0;
}

}  // namespace raypoint::daemon
