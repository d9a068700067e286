// SPDX-License-Identifier: MIT
#include "preview_window.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>

#include <opencv2/highgui.hpp>

#include "input_error.hpp"
#include "plot_command.hpp"
#include "raypoint/config/ini_update.hpp"

namespace raypoint::daemon {
namespace {

constexpr std::array<Tunable, 6> tunable_list{{
    {"preprocess", "edge_threshold", "edge threshold", 1.0, 254},
    // Movement sums over 160x120 pixels; the bar in hundreds up to 200,000 (an average of 10).
    {"tracking", "search_threshold", "search /100", 0.01, 2000},
    {"tracking", "idle_threshold", "idle /100", 0.01, 2000},
    {"tracking", "min_area", "min area x1000", 1000.0, 300},
    {"tracking", "max_area", "max area x100", 100.0, 100},
    {"click", "press_rise", "press rise x100", 100.0, 100},
}};

std::atomic<bool> stop_requested{false};

extern "C" void on_stop_signal(int) {
    stop_requested = true;
}

double current_value(const config::Key& key, const config::Config& config) {
    return std::stod(key.format(config));
}

struct Trackbars {
    std::array<int, tunable_list.size()> positions{};
    bool changed = false;
};

void on_trackbar(int, void* data) {
    static_cast<Trackbars*>(data)->changed = true;
}

// The trackbars' positions as settings: each through the schema, then the cross-checks; a
// position the schema refuses puts the bar back.
void apply_trackbars(const std::string& window, view::PreviewSession& session) {
    config::Config config = session.config();
    for (const Tunable& tunable : tunable_list) {
        const config::Key* key = config::find_key(tunable.section, tunable.name);
        const int position = cv::getTrackbarPos(tunable.label, window);
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", position / tunable.scale);
        if (const auto error = key->set(config, text)) {
            std::fprintf(stderr, "raypoint preview: %s = %s: %s\n", key->full_name().c_str(), text,
                         error->c_str());
        }
    }
    const auto problems = config::cross_check(config);
    if (!problems.empty()) {
        std::fprintf(stderr, "raypoint preview: %s (kept the previous values)\n",
                     problems.front().c_str());
        for (const Tunable& tunable : tunable_list) {
            const config::Key* key = config::find_key(tunable.section, tunable.name);
            cv::setTrackbarPos(tunable.label, window,
                               static_cast<int>(std::lround(current_value(*key, session.config()) *
                                                            tunable.scale)));
        }
        return;
    }
    session.set_config(config);
}

}  // namespace

std::span<const Tunable> tunables() {
    return tunable_list;
}

std::vector<const config::Key*> tunable_keys() {
    std::vector<const config::Key*> keys;
    keys.reserve(tunable_list.size());
    for (const Tunable& tunable : tunable_list)
        keys.push_back(config::find_key(tunable.section, tunable.name));
    return keys;
}

int run_preview_loop(FrameSource& source, view::PreviewSession& session,
                     const PreviewLoopOptions& options) {
    stop_requested = false;
    const auto previous_int = std::signal(SIGINT, on_stop_signal);
    const auto previous_term = std::signal(SIGTERM, on_stop_signal);
    session.set_view(options.view);
    Trackbars bars;
    if (!options.headless) {
        cv::namedWindow(options.title, cv::WINDOW_AUTOSIZE);
        for (std::size_t i = 0; i < tunable_list.size(); ++i) {
            const Tunable& tunable = tunable_list[i];
            const config::Key* key = config::find_key(tunable.section, tunable.name);
            cv::createTrackbar(tunable.label, options.title, nullptr, tunable.max, on_trackbar,
                               &bars);
            cv::setTrackbarPos(tunable.label, options.title,
                               static_cast<int>(std::lround(current_value(*key, session.config()) *
                                                            tunable.scale)));
        }
        bars.changed = false;
        std::printf("raypoint preview: v edges/difference, space pause, w write %s, q quit\n",
                    options.ini.c_str());
        std::fflush(stdout);
    }
    int frames = 0;
    bool ended = false;
    while (!stop_requested && !ended && !(options.frames && frames >= *options.frames)) {
        if (!session.paused()) {
            const Capture capture = source.next(1000);
            switch (capture.status) {
                case CaptureStatus::frame:
                    session.process(capture.frame);
                    ++frames;
                    break;
                case CaptureStatus::timeout:
                    break;
                case CaptureStatus::ended:
                    ended = true;
                    break;
                case CaptureStatus::lost:
                    throw InputError("camera lost: " + capture.reason);
            }
        }
        if (options.headless) continue;
        const cv::Mat picture = session.render();
        if (!picture.empty()) cv::imshow(options.title, picture);
        const int key = cv::waitKey(session.paused() ? 30 : 1);
        if (bars.changed) {
            bars.changed = false;
            apply_trackbars(options.title, session);
        }
        switch (key & 0xff) {
            case 'q':
            case 27:
                stop_requested = true;
                break;
            case 'v':
                session.set_view(session.view() == view::BackgroundView::edges
                                     ? view::BackgroundView::difference
                                     : view::BackgroundView::edges);
                break;
            case ' ':
                session.set_paused(!session.paused());
                break;
            case 'w': {
                // A file that cannot be written is said, and the preview goes on.
                const auto keys = tunable_keys();
                try {
                    config::write_ini_values(options.ini, session.config(), keys);
                    std::printf("raypoint preview: wrote %zu settings to %s\n", keys.size(),
                                options.ini.c_str());
                } catch (const std::exception& e) {
                    std::printf("raypoint preview: not written: %s\n", e.what());
                }
                std::fflush(stdout);
                break;
            }
            default:
                break;
        }
    }
    if (!options.headless) cv::destroyWindow(options.title);
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
    if (!options.screenshot.empty()) write_png(session.render(), options.screenshot);
    return frames;
}

}  // namespace raypoint::daemon
