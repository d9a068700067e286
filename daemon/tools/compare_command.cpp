// SPDX-License-Identifier: MIT
#include "compare_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "input_error.hpp"
#include "raypoint/cli/output_path.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {
namespace {

// One estimator configuration under comparison.
struct Contender {
    std::string name;
    core::EstimatorSettings settings;
};

struct Tally {
    std::vector<double> centroid_errors;  // working pixels
    std::vector<double> area_errors;      // relative
    std::vector<double> iterations;
    std::vector<double> microseconds;
    int on_target = 0;
    int samples = 0;
};

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// Start points inside the target and off its edge band (the band lies partly inside the mask,
// and rays from an edge pixel have no length): the widest place (farthest from the band and
// the outline) and an isolated one (the open inside point farthest from the widest: a
// fingertip of the hand, the rim of the sphere).
void start_points(const cv::Mat& mask, const cv::Mat& edges, cv::Point2f& wide,
                  cv::Point2f& isolated) {
    cv::Mat open = mask.clone();
    open.setTo(0, edges);
    cv::Mat distance;
    cv::distanceTransform(open, distance, cv::DIST_L2, 3);
    cv::Point widest;
    cv::minMaxLoc(distance, nullptr, nullptr, nullptr, &widest);
    wide = cv::Point2f(static_cast<float>(widest.x), static_cast<float>(widest.y));
    double farthest = -1.0;
    for (int y = 0; y < mask.rows; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            if (distance.at<float>(y, x) < 1.0F) continue;
            const double d = std::hypot(x - widest.x, y - widest.y);
            if (d > farthest) {
                farthest = d;
                isolated = cv::Point2f(static_cast<float>(x), static_cast<float>(y));
            }
        }
    }
}

std::string run(const config::Config& config, const std::vector<Contender>& contenders,
                int samples_wanted) {
    std::ostringstream out;
    const core::PreprocessSettings& preprocess = config.core.preprocess;
    const cv::Size working(preprocess.work_width, preprocess.work_height);
    for (const char* scene_name : {"ideal", "nonconvex"}) {
        const scene::Renderer renderer(scene::preset(scene_name));
        const scene::SceneSpec& spec = renderer.spec();
        std::vector<int> frames;
        for (int i = 0; i < renderer.frame_count(); ++i) {
            if (renderer.frame_time(i) >= spec.empty_seconds + 1.0) frames.push_back(i);
        }
        const std::size_t step =
            std::max<std::size_t>(1, (frames.size() + samples_wanted - 1) / samples_wanted);
        std::vector<std::array<Tally, 2>> tallies(contenders.size());
        int sampled = 0;
        for (std::size_t f = 0; f < frames.size(); f += step) {
            const scene::RenderedFrame frame = renderer.render(frames[f]);
            if (!frame.truth.present) continue;
            ++sampled;
            core::Preprocessor preprocessor(preprocess);
            preprocessor.process({frame.bgr.data, frame.bgr.cols, frame.bgr.rows,
                                  static_cast<int>(frame.bgr.step), core::PixelFormat::bgr, 0});
            cv::Mat mask;
            cv::resize(frame.mask, mask, working, 0, 0, cv::INTER_AREA);
            cv::threshold(mask, mask, 127, 255, cv::THRESH_BINARY);
            cv::Point2f starts[2];
            start_points(mask, preprocessor.edges(), starts[0], starts[1]);
            // Truth in working pixel-centre coordinates and square working pixels.
            const cv::Point2f centroid(static_cast<float>(frame.truth.cx * working.width - 0.5),
                                       static_cast<float>(frame.truth.cy * working.height - 0.5));
            const double area = frame.truth.area * working.area();
            for (std::size_t c = 0; c < contenders.size(); ++c) {
                auto estimator = core::make_estimator(contenders[c].settings);
                for (int s = 0; s < 2; ++s) {
                    core::Estimate estimate{};
                    constexpr int repetitions = 20;
                    const auto begin = std::chrono::steady_clock::now();
                    for (int r = 0; r < repetitions; ++r) {
                        estimate = estimator->estimate(preprocessor.edges(), starts[s]);
                    }
                    const double us = std::chrono::duration<double, std::micro>(
                                          std::chrono::steady_clock::now() - begin)
                                          .count() /
                                      repetitions;
                    Tally& tally = tallies[c][s];
                    ++tally.samples;
                    tally.centroid_errors.push_back(cv::norm(estimate.centroid - centroid));
                    tally.area_errors.push_back(std::abs(estimate.area - area) / area);
                    tally.iterations.push_back(estimate.iterations);
                    tally.microseconds.push_back(us);
                    const cv::Point p(cvRound(estimate.centroid.x), cvRound(estimate.centroid.y));
                    if (cv::Rect(0, 0, mask.cols, mask.rows).contains(p) &&
                        mask.at<std::uint8_t>(p) != 0) {
                        ++tally.on_target;
                    }
                }
            }
        }
        const char* target =
            std::string(scene_name) == "ideal" ? "convex (sphere)" : "non-convex (hand)";
        for (int s = 0; s < 2; ++s) {
            out << "\n### " << target << " (" << sampled << " frames), inner point started "
                << (s == 0 ? "in the widest area" : "in an isolated area (fingertip / rim)")
                << "\n\n| estimator | centroid error px (median) | area error (median) | "
                   "centroid on target | iterations (median) | us (median) |\n"
                   "|---|---|---|---|---|---|\n";
            for (std::size_t c = 0; c < contenders.size(); ++c) {
                const Tally& t = tallies[c][s];
                char row[256];
                std::snprintf(row, sizeof row, "| %s | %.2f | %.1f%% | %d/%d | %.0f | %.1f |\n",
                              contenders[c].name.c_str(), median(t.centroid_errors),
                              100.0 * median(t.area_errors), t.on_target, t.samples,
                              median(t.iterations), median(t.microseconds));
                out << row;
            }
        }
    }
    return out.str();
}

}  // namespace

int compare_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest);
    std::string out_path;
    int samples = 40;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == "--out") {
            out_path = option_value(rest, i);
        } else {
            throw UsageError(std::string(rest[i]) + ": unknown option (see raypoint --help)");
        }
    }
    if (!out_path.empty()) check_output_path("--out", out_path);
    std::vector<Contender> contenders;
    for (const auto kind : {core::EstimatorKind::ray, core::EstimatorKind::iterative_ray,
                            core::EstimatorKind::iterative_ny_ray, core::EstimatorKind::raster}) {
        core::EstimatorSettings settings = config.core.estimator;
        settings.kind = kind;
        if (kind == core::EstimatorKind::raster) {
            settings.area_mode = core::AreaMode::blocks;
            contenders.push_back({"raster, blocks (paper 3.4)", settings});
            settings.area_mode = core::AreaMode::refined;
            contenders.push_back({"raster, refined (default)", settings});
        } else {
            contenders.push_back({std::string(core::to_string(kind)), settings});
        }
    }
    const auto& e = config.core.estimator;
    std::ostringstream doc;
    doc << "# The four estimators, measured\n\n"
           "Generated by `build/raypoint compare-estimators --out docs/estimators.md`; do not edit "
           "by "
           "hand. The paper (section 3) claims each estimator beats the one before; this is what "
           "they do on the project's own rendered scenes (`ideal`: a sphere; `nonconvex`: a "
           "paper hand with spread fingers; both on a white board, 640x480), "
        << "about " << samples
        << " frames each, after the default preprocessing (160x120, edges over "
        << config.core.preprocess.edge_threshold << "). n = " << e.rays << ", y = " << e.recasts
        << ", m = " << e.block_size << ", at most " << e.max_iterations << " iterations, tolerance "
        << e.tolerance
        << " px. Errors are against the rendered mask's exact centroid and area, in working "
           "pixels; *centroid on target* counts estimates whose centroid lies inside the "
           "target; times are one core, median of 20 runs a frame.\n";
    doc << run(config, contenders, samples);
    doc << "\nReading: see docs/estimators-reading.md.\n";
    if (out_path.empty()) {
        std::fputs(doc.str().c_str(), stdout);
    } else {
        std::ofstream file(out_path);
        file << doc.str();
        if (!file) throw InputError(out_path + ": cannot write");
    }
    return 0;
}

}  // namespace raypoint::daemon
