// SPDX-License-Identifier: MIT
#include "bench_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "bench_clip.hpp"
#include "bench_report.hpp"
#include "bench_runner.hpp"
#include "input_error.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/scene/presets.hpp"

namespace raypoint::daemon {
namespace {

// The rendered scenes measured without CLIP: one a condition of the paper's tests (section 5)
// plus the fast and paused motions.
constexpr const char* default_scenes = "ideal,lowlight,interfering,nonconvex,realworld,fast,pause";

struct BenchOptions {
    std::vector<std::string> clips;
    std::vector<std::string> scenes;
    std::vector<PeerKind> peers = all_peers();
    BenchFormat format = BenchFormat::table;
    int frames = 0;  // 0: every frame
};

std::vector<std::string> split(std::string_view list) {
    std::vector<std::string> items;
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string_view item = list.substr(0, comma);
        if (!item.empty()) items.emplace_back(item);
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
    return items;
}

BenchOptions parse_bench_options(std::span<const std::string_view> args) {
    BenchOptions options;
    options.scenes = split(default_scenes);
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (arg == "--format") {
            const std::string_view value = option_value(args, i);
            if (value == "table") {
                options.format = BenchFormat::table;
            } else if (value == "markdown") {
                options.format = BenchFormat::markdown;
            } else if (value == "jsonl") {
                options.format = BenchFormat::jsonl;
            } else {
                throw UsageError("--format " + std::string(value) +
                                 ": unknown format (allowed: table|markdown|jsonl)");
            }
        } else if (arg == "--peers") {
            const std::string_view value = option_value(args, i);
            options.peers.clear();
            for (const std::string& name : split(value)) {
                PeerKind kind{};
                if (name == "none") continue;
                if (!peer_from_string(name, kind)) {
                    throw UsageError("--peers " + std::string(value) + ": unknown peer '" + name +
                                     "' (allowed: camshift,kcf,csrt,mil or none)");
                }
                options.peers.push_back(kind);
            }
        } else if (arg == "--scenes") {
            const std::string_view value = option_value(args, i);
            options.scenes = split(value);
            if (options.scenes.empty()) throw UsageError("--scenes: empty list");
        } else if (arg == "--frames") {
            const std::string value(option_value(args, i));
            char* end = nullptr;
            const long frames = std::strtol(value.c_str(), &end, 10);
            if (end == value.c_str() || *end != '\0' || frames < 2 || frames > 1000000) {
                throw UsageError("--frames " + value + ": not a frame count (allowed: 2..1000000)");
            }
            options.frames = static_cast<int>(frames);
        } else if (arg.starts_with("-") && arg.size() > 1) {
            throw UsageError(std::string(arg) + ": unknown option (see raypoint --help)");
        } else {
            options.clips.emplace_back(arg);
        }
    }
    return options;
}

// Says on stderr what is running, only when a person watches (never in pipes or logs).
void progress(const std::string& text) {
    if (isatty(STDERR_FILENO) == 0) return;
    std::fprintf(stderr, "\r\033[Kbench: %s", text.c_str());
    std::fflush(stderr);
}

ClipResults measure(const BenchClip& clip, const core::Settings& settings,
                    const std::vector<PeerKind>& peers) {
    if (clip.frames.size() < 2) throw InputError(clip.name + ": fewer than 2 frames");
    ClipResults results;
    results.clip = clip.name;
    const PeerStart start = peer_start(clip);
    for (const auto kind : {core::EstimatorKind::ray, core::EstimatorKind::iterative_ray,
                            core::EstimatorKind::iterative_ny_ray, core::EstimatorKind::raster}) {
        core::Settings variant = settings;
        variant.estimator.kind = kind;
        progress(clip.name + ": raypoint " + std::string(core::to_string(kind)));
        results.systems.push_back(run_raypoint(clip, variant, start));
    }
    // MIL (and CSRT, KCF) draw from OpenCV's global generator: start each clip's peers from its
    // default seed, as the scoring method's process a scene does, so a clip's figures do not depend
    // on the clips before it. They still depend on the peers before them, as in the scoring method.
    cv::theRNG() = cv::RNG();
    for (const PeerKind peer : peers) {
        progress(clip.name + ": " + std::string(to_string(peer)));
        results.systems.push_back(run_peer(clip, peer, start));
    }
    return results;
}

}  // namespace

int bench_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest);
    const BenchOptions options = parse_bench_options(rest);
    // Fail on a missing clip or an unknown scene before spending minutes on the ones before it.
    for (const std::string& name :
         options.clips.empty() ? options.scenes : std::vector<std::string>{}) {
        try {
            scene::preset(name);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--scenes: ") + e.what());
        }
    }
    for (const std::string& clip : options.clips)
        check_clip(clip);
    // One core for everyone: OpenCV would spread the peers' (and imgproc's) loops over every
    // core, which the daemon, running all day in the background, must not do.
    cv::setNumThreads(1);
    std::vector<ClipResults> results;
    const auto& inputs = options.clips.empty() ? options.scenes : options.clips;
    for (const std::string& input : inputs) {
        progress(input + ": " + (options.clips.empty() ? "rendering" : "decoding"));
        // Every frame in memory before any timing; one clip at a time.
        const BenchClip clip = options.clips.empty() ? render_clip(input, options.frames)
                                                     : load_clip(input, options.frames);
        results.push_back(measure(clip, config.core, options.peers));
    }
    if (isatty(STDERR_FILENO) != 0) std::fputs("\r\033[K", stderr);
    const std::string reference =
        "raypoint " + std::string(core::to_string(config.core.estimator.kind));
    if (options.format == BenchFormat::table) {
        std::printf(
            "# raypoint bench: microseconds a frame on one core (OpenCV threads: 1), decoded "
            "frames in memory; "
            "peers started from the true box; x default = median / %s's median\n",
            reference.c_str());
    }
    print_rows(stdout, bench_rows(results, reference), options.format);
    std::fflush(stdout);
    return 0;
}

}  // namespace raypoint::daemon
