// SPDX-License-Identifier: MIT
#include "demo_command.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include <opencv2/videoio.hpp>

#include "annotator.hpp"
#include "input_error.hpp"
#include "raypoint/cli/output_path.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/scene/evaluation.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {
namespace {

std::string optional_number(const std::optional<double>& value, const char* format) {
    if (!value) return "-";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, format, *value);
    return buffer;
}

}  // namespace

int demo_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest);
    std::string scene_name = "nonconvex";
    std::string annotate_path = "raypoint-demo.mp4";
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == "--scene") {
            scene_name = option_value(rest, i);
        } else if (rest[i] == "--annotate") {
            annotate_path = option_value(rest, i);
        } else {
            throw UsageError(std::string(rest[i]) + ": unknown option (see raypoint --help)");
        }
    }
    check_output_path("--annotate", annotate_path);
    scene::SceneSpec spec;
    try {
        spec = scene::preset(scene_name);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--scene: ") + e.what());
    }
    const scene::Renderer renderer(spec);
    core::Tracker tracker(config.core);
    scene::Evaluator evaluator;
    cv::VideoWriter annotated(annotate_path, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), spec.fps,
                              cv::Size(spec.width, spec.height));
    if (!annotated.isOpened()) {
        throw InputError(annotate_path + ": cannot write video (check the folder)");
    }
    std::printf("# raypoint demo: scene '%s' (%dx%d, %.0f fps, %.1f s), rendered in memory\n",
                spec.name.c_str(), spec.width, spec.height, spec.fps, spec.seconds);
    std::printf("# %6s  %-12s  %8s %8s %8s   %s\n", "t (s)", "state", "x", "y", "z", "truth x y");
    long total_us = 0;
    for (int index = 0; index < renderer.frame_count(); ++index) {
        scene::RenderedFrame frame = renderer.render(index);
        const core::FrameView view{
            frame.bgr.data,         frame.bgr.cols,
            frame.bgr.rows,         static_cast<int>(frame.bgr.step),
            core::PixelFormat::bgr, core::seconds_to_us(renderer.frame_time(index))};
        const auto start = std::chrono::steady_clock::now();
        const core::FrameResult result = tracker.process(view);
        total_us += static_cast<long>(std::chrono::duration_cast<std::chrono::microseconds>(
                                          std::chrono::steady_clock::now() - start)
                                          .count());
        evaluator.add(frame.truth, frame.mask, result);
        std::string truth = frame.truth.present
                                ? std::to_string(frame.truth.cx).substr(0, 6) + " " +
                                      std::to_string(frame.truth.cy).substr(0, 6)
                                : "absent";
        if (result.has_position) {
            std::printf("  %6.2f  %-12s  %8.4f %8.4f %+8.4f   %s\n", frame.truth.t,
                        std::string(core::to_string(result.state)).c_str(), result.position.x,
                        result.position.y, result.position.z, truth.c_str());
        } else {
            std::printf("  %6.2f  %-12s  %8s %8s %8s   %s\n", frame.truth.t,
                        std::string(core::to_string(result.state)).c_str(), "-", "-", "-",
                        truth.c_str());
        }
        annotate(frame.bgr, tracker, result);
        annotated.write(frame.bgr);
    }
    const scene::Evaluation e = evaluator.result();
    std::printf(
        "# on target in %.1f%% of %d moving frames; median centroid error %s px at 160x120; "
        "median area error %s; z vs 1/depth r = %s; detected %s s after the target first "
        "moved; core %.0f us a frame\n",
        100.0 * e.tracked(), e.scored_frames,
        optional_number(e.median_centroid_error, "%.2f").c_str(),
        optional_number(e.median_area_error, "%.3f").c_str(),
        optional_number(e.depth_correlation, "%.3f").c_str(),
        optional_number(e.detection_delay, "%.2f").c_str(),
        static_cast<double>(total_us) / renderer.frame_count());
    std::printf("# annotated clip: %s\n", annotate_path.c_str());
    return 0;
}

}  // namespace raypoint::daemon
