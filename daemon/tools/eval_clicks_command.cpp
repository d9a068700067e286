// SPDX-License-Identifier: MIT
#include "eval_clicks_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "click_eval.hpp"
#include "click_report.hpp"
#include "gesture_files.hpp"
#include "input_error.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {
namespace {

struct EvalOptions {
    std::string set = "full";
    std::uint32_t seed = 1;
    int jobs = 1;
    bool sweep = false;
    std::string plot;        // PNG of the sweep
    std::string write_dir;   // the rendered set as videos with their truth files
    std::string photos_dir;  // --backgrounds: the set in front of these photographs
    // The tracker's results of each rendered clip, kept in DIR/NAME.results and read back while
    // the file exists (remove them after changing tracking settings or the tracker): a sweep
    // of the click settings on the same tracking, in seconds.
    std::string cache_dir;
    bool misses = false;             // --misses: why each miss and false press happened, on stderr
    std::string trace;               // --trace: each frame of the clip of that name, on stderr
    std::vector<std::string> clips;  // recorded: VIDEO, truth in VIDEO.clicks
    // --require: limits on the overall figures (the target pushes' recall); exit 1 when missed.
    std::optional<double> min_recall;      // fraction
    std::optional<double> max_false;       // per minute
    std::optional<double> max_latency_ms;  // median
    std::optional<double> max_offset_px;   // median
    // Right click, double click and scroll, each (those the set has): recognised at least this
    // fraction, and neither they nor the left clicks and drags taken for one another more.
    std::optional<double> min_gesture_recall;
    std::optional<double> max_confusion;
};

double parse_real(std::string_view option, std::string_view text) {
    const std::string value(text);
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end == value.c_str() || *end != '\0' || !(v >= 0)) {
        throw UsageError(std::string(option) + " " + value + ": not a number >= 0");
    }
    return v;
}

long parse_integer(std::string_view option, std::string_view text, long low, long high) {
    const std::string value(text);
    char* end = nullptr;
    const long n = std::strtol(value.c_str(), &end, 10);
    if (end == value.c_str() || *end != '\0' || n < low || n > high) {
        throw UsageError(std::string(option) + " " + value + ": not a whole number (allowed: " +
                         std::to_string(low) + ".." + std::to_string(high) + ")");
    }
    return n;
}

EvalOptions parse_eval_options(std::span<const std::string_view> args) {
    EvalOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (arg == "--set-name") {
            options.set = std::string(option_value(args, i));
            if (options.set != "full" && options.set != "ci" && options.set != "none") {
                throw UsageError("--set-name " + options.set + ": unknown (allowed: full|ci|none)");
            }
        } else if (arg == "--seed") {
            options.seed = static_cast<std::uint32_t>(
                parse_integer(arg, option_value(args, i), 0, 0x7fffffff));
        } else if (arg == "--jobs") {
            options.jobs = static_cast<int>(parse_integer(arg, option_value(args, i), 1, 64));
        } else if (arg == "--sweep") {
            options.sweep = true;
        } else if (arg == "--plot") {
            options.plot = std::string(option_value(args, i));
            options.sweep = true;
        } else if (arg == "--min-recall") {
            options.min_recall = parse_real(arg, option_value(args, i));
        } else if (arg == "--max-false-per-minute") {
            options.max_false = parse_real(arg, option_value(args, i));
        } else if (arg == "--max-latency-ms") {
            options.max_latency_ms = parse_real(arg, option_value(args, i));
        } else if (arg == "--max-offset-px") {
            options.max_offset_px = parse_real(arg, option_value(args, i));
        } else if (arg == "--min-gesture-recall") {
            options.min_gesture_recall = parse_real(arg, option_value(args, i));
        } else if (arg == "--max-confusion") {
            options.max_confusion = parse_real(arg, option_value(args, i));
        } else if (arg == "--misses") {
            options.misses = true;
        } else if (arg == "--trace") {
            options.trace = std::string(option_value(args, i));
        } else if (arg == "--cache") {
            options.cache_dir = std::string(option_value(args, i));
        } else if (arg == "--write") {
            options.write_dir = std::string(option_value(args, i));
        } else if (arg == "--backgrounds") {
            options.photos_dir = std::string(option_value(args, i));
        } else if (arg.starts_with("-") && arg.size() > 1) {
            throw UsageError(std::string(arg) + ": unknown option (see raypoint --help)");
        } else {
            options.clips.emplace_back(arg);
        }
    }
    return options;
}

void progress(int done, int total) {
    if (isatty(STDERR_FILENO) == 0) return;
    std::fprintf(stderr, "\r\033[Keval-clicks: tracked %d of %d clips", done, total);
    std::fflush(stderr);
}

// What the pointer reads of a frame's result, in the host's byte order. The file's suffix
// changes with this layout, so a cache of another layout is never misread.
struct CachedResult {
    core::Timestamp timestamp;
    std::int32_t state;
    std::int32_t flags;  // 1: has_position, 2: has_target, 4: recovered, 8: lost, 16: followed
    double x, y;         // smoothed position
    double area;         // < 0: none
    double centroid_x, centroid_y;
    double region_x, region_y;  // the region's centroid when followed
    double inner_x, inner_y;
    double movement;
    double light_change;
};
constexpr const char* cache_suffix = ".results4";

TrackedClip cached_track(const scene::GestureClip& clip, const core::Settings& settings,
                         const std::string& dir, const std::string& set, std::uint32_t seed) {
    if (dir.empty()) return track_rendered(clip, settings);
    // The clips' names repeat from set to set and seed to seed (the ci set's lean-0 is not the
    // full set's): each set and seed has its own folder.
    const std::string folder = dir + "/" + set + "-seed-" + std::to_string(seed);
    const std::string path = folder + "/" + clip.spec.name + cache_suffix;
    std::ifstream in(path, std::ios::binary);
    if (in) {
        TrackedClip tracked = track_rendered_truth(clip);
        CachedResult c{};
        while (in.read(reinterpret_cast<char*>(&c), sizeof c)) {
            core::FrameResult r;
            r.timestamp = c.timestamp;
            r.state = static_cast<core::TrackerState>(c.state);
            r.has_position = (c.flags & 1) != 0;
            r.has_target = (c.flags & 2) != 0;
            r.recovered = (c.flags & 4) != 0;
            r.lost = (c.flags & 8) != 0;
            r.followed = (c.flags & 16) != 0;
            r.position = cv::Point3d(c.x, c.y, 0);
            if (c.area >= 0) r.area = c.area;
            r.centroid = cv::Point2d(c.centroid_x, c.centroid_y);
            r.region_centroid = cv::Point2d(c.region_x, c.region_y);
            r.inner = cv::Point2d(c.inner_x, c.inner_y);
            r.movement = c.movement;
            r.light_change = c.light_change;
            tracked.results.push_back(r);
        }
        return tracked;
    }
    TrackedClip tracked = track_rendered(clip, settings);
    std::filesystem::create_directories(folder);
    std::ofstream out(path, std::ios::binary);
    for (const core::FrameResult& r : tracked.results) {
        const std::int32_t flags = (r.has_position ? 1 : 0) | (r.has_target ? 2 : 0) |
                                   (r.recovered ? 4 : 0) | (r.lost ? 8 : 0) | (r.followed ? 16 : 0);
        const CachedResult c{r.timestamp,
                             static_cast<std::int32_t>(r.state),
                             flags,
                             r.position.x,
                             r.position.y,
                             r.area.value_or(-1.0),
                             r.centroid.x,
                             r.centroid.y,
                             r.region_centroid.x,
                             r.region_centroid.y,
                             r.inner.x,
                             r.inner.y,
                             r.movement,
                             r.light_change};
        out.write(reinterpret_cast<const char*>(&c), sizeof c);
    }
    if (!out) throw InputError(path + ": cannot write the cache");
    // The truth beside the results, for whoever studies the cache.
    std::ofstream truth(folder + "/" + clip.spec.name + ".clicks");
    truth << scene::click_truth_text(clip);
    if (!truth) throw InputError(folder + "/" + clip.spec.name + ".clicks: cannot write");
    return tracked;
}

// Every clip through the tracker, `jobs` at a time (each clip has its own tracker).
std::vector<TrackedClip> track_all(const std::vector<scene::GestureClip>& set,
                                   const EvalOptions& options, const core::Settings& settings) {
    const int total = static_cast<int>(set.size() + options.clips.size());
    std::vector<TrackedClip> tracked(static_cast<std::size_t>(total));
    std::atomic<int> next{0};
    std::atomic<int> done{0};
    std::mutex failure_lock;
    std::string failure;
    auto work = [&] {
        for (int i = next++; i < total; i = next++) {
            const auto index = static_cast<std::size_t>(i);
            try {
                if (index < set.size()) {
                    // In front of photographs the clips are not the set's: their own folder.
                    tracked[index] = cached_track(
                        set[index], settings, options.cache_dir,
                        options.photos_dir.empty() ? options.set : options.set + "-photos",
                        options.seed);
                } else {
                    const std::string& video = options.clips[index - set.size()];
                    tracked[index] = track_recorded(video, video + ".clicks", settings);
                }
            } catch (const std::exception& e) {
                const std::lock_guard lock(failure_lock);
                failure = e.what();
            }
            progress(++done, total);
        }
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < options.jobs; ++j)
        threads.emplace_back(work);
    work();
    for (std::thread& thread : threads)
        thread.join();
    if (isatty(STDERR_FILENO) != 0) std::fputs("\r\033[K", stderr);
    if (!failure.empty()) throw InputError(failure);
    return tracked;
}

Tallies score_all(const std::vector<TrackedClip>& clips, const core::PointerSettings& settings,
                  const core::OutputSettings& output, std::FILE* misses = nullptr,
                  std::string_view trace = {}) {
    Tallies tallies;
    for (const TrackedClip& clip : clips)
        score_clip(clip, settings, output, tallies, misses, trace.empty() ? nullptr : stderr,
                   trace);
    return tallies;
}

// The sweep of docs/clicks.md: press_rise along each series; push_seconds (the settings' and two
// longer) and the time the rise must be held (press_hold_seconds) across them.
std::vector<SweepPoint> sweep(const std::vector<TrackedClip>& clips,
                              const core::PointerSettings& base,
                              const core::OutputSettings& output) {
    std::vector<SweepPoint> points;
    for (const double hold : {0.0, 0.05}) {
        for (const double push : {base.click.push_seconds, 0.4, 0.6}) {
            char series[64];
            std::snprintf(series, sizeof series, "push %.2f s, hold %.2f s", push, hold);
            for (const double rise : {0.10, 0.12, 0.14, 0.16, 0.18, 0.20, 0.25}) {
                core::PointerSettings settings = base;
                settings.click.press_rise = rise;
                settings.click.release_rise = std::min(settings.click.release_rise, rise / 2);
                settings.click.push_seconds = push;
                settings.click.press_hold_seconds = hold;
                const Tallies tallies = score_all(clips, settings, output);
                char label[32];
                std::snprintf(label, sizeof label, "%.2f", rise);
                const Tally& target = tallies.contains("target") ? tallies.at("target") : Tally{};
                const Tally& all = tallies.contains("all") ? tallies.at("all") : Tally{};
                points.push_back({label, series, target.press_recall(), all.false_per_minute()});
            }
        }
    }
    return points;
}

// The --min/--max limits against the figures: a line on stderr for each missed, and whether all
// were met.
bool meets(const EvalOptions& options, const Tallies& tallies) {
    const Tally none;
    const Tally& target = tallies.contains("target") ? tallies.at("target") : none;
    const Tally& all = tallies.contains("all") ? tallies.at("all") : none;
    bool ok = true;
    auto check = [&](const std::optional<double>& limit, double value, bool at_least,
                     const char* what) {
        if (!limit) return;
        if (std::isnan(value) || (at_least ? value < *limit : value > *limit)) {
            std::fprintf(stderr, "eval-clicks: %s %.3f, %s %.3f required\n", what, value,
                         at_least ? "at least" : "at most", *limit);
            ok = false;
        }
    };
    check(options.min_recall, target.press_recall(), true, "target pushes pressed");
    check(options.max_false, all.false_per_minute(), false, "false clicks a minute");
    // Of the target pushes, as the table's latency target is: a slower, shallower push that
    // presses at all presses later, and must not count against the limit for pressing.
    check(options.max_latency_ms, median(target.latencies) * 1000, false,
          "median latency of the target pushes (ms)");
    check(options.max_offset_px, median(all.offsets), false, "median offset (px)");
    const std::pair<const char*, const GestureTally*> gestures[] = {
        {"right click", &all.right}, {"double click", &all.double_click}, {"scroll", &all.scroll}};
    for (const auto& [name, g] : gestures) {
        if (g->count == 0) continue;
        const std::string what(name);
        check(options.min_gesture_recall, double(g->found) / g->count, true,
              (what + " recognised").c_str());
        check(options.max_confusion, double(g->as_left) / g->count, false,
              (what + " taken for a left click").c_str());
    }
    if (all.gestures() > 0) {
        check(options.max_confusion, double(all.left_as_other) / all.gestures(), false,
              "left clicks and drags taken for another gesture");
    }
    return ok;
}

// `only`: the one clip of that name (--trace), so a clip --misses names can be looked at with
// `raypoint track --annotate` without rendering the whole set; empty: every clip.
}  // namespace

int eval_clicks_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest);
    const EvalOptions options = parse_eval_options(rest);
    for (const std::string& clip : options.clips) {
        if (!std::filesystem::exists(clip + ".clicks"))
            throw InputError(clip + ".clicks: no click truth beside the clip");
    }
    cv::setNumThreads(1);
    std::vector<scene::GestureClip> set = options.set == "none"
                                              ? std::vector<scene::GestureClip>{}
                                              : scene::gesture_set(options.set, options.seed);
    if (!options.photos_dir.empty())
        scene::use_photos(set, photos_in(options.photos_dir), options.seed);
    if (!options.write_dir.empty()) {
        write_set(set, options.write_dir, options.trace);
        return 0;
    }
    // A recorded clip's name is its path, as given.
    if (!options.trace.empty() &&
        std::none_of(
            set.begin(), set.end(),
            [&](const scene::GestureClip& clip) { return clip.spec.name == options.trace; }) &&
        std::find(options.clips.begin(), options.clips.end(), options.trace) ==
            options.clips.end()) {
        throw UsageError("--trace " + options.trace +
                         ": no clip of that name (--misses names them, such as push-006)");
    }
    const std::vector<TrackedClip> tracked = track_all(set, options, config.core);
    std::printf("# raypoint eval-clicks: gesture set '%s' (seed %u)%s%s, %zu recorded clips\n\n",
                options.set.c_str(), options.seed,
                options.photos_dir.empty() ? "" : " in front of the photographs in ",
                options.photos_dir.c_str(), options.clips.size());
    const Tallies tallies = score_all(tracked, config.core.pointer, config.core.output,
                                      options.misses ? stderr : nullptr, options.trace);
    print_tallies(stdout, tallies);
    std::printf("\n");
    print_gestures(stdout, tallies);
    if (options.sweep) {
        const std::vector<SweepPoint> points =
            sweep(tracked, config.core.pointer, config.core.output);
        std::printf("\n");
        print_sweep(stdout, points);
        if (!options.plot.empty()) plot_sweep(options.plot, points);
    }
    std::fflush(stdout);
    return meets(options, tallies) ? 0 : 1;
}

}  // namespace raypoint::daemon
