// SPDX-License-Identifier: MIT
// raypoint-soak: hours of frames through the daemon's loop, faster than real time.
//   raypoint-soak [--frames N] [--clip PRESET]
// The rendered clip (default `click`: the hand moves, pushes once, moves on; 320x240, 30 fps) is
// played again and again with its time going on, through PointerDaemon::run(), the core and the
// pointer into a model of the uinput device (tests/daemon/fault_harness.hpp). 108,000 frames are
// an hour at 30 fps. Checks, each failing the run (exit 1):
//   - memory flat: resident set after the first loop and at the end within 1 MiB (a leak of 10
//     bytes a frame is 1 MiB in an hour);
//   - nothing stuck: the last whole loop clicks and moves the pointer as the first one did;
//   - every press released: presses equal releases, no button down at the end.
// Prints one line with the figures (docs/reliability.md's soak row).

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

#include "fault_harness.hpp"
#include "raypoint/loop/pointer_daemon.hpp"

namespace {

using namespace raypoint::daemon;

double resident_mib() {
    std::ifstream statm("/proc/self/statm");
    long long size = 0;
    long long resident = 0;
    statm >> size >> resident;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

struct LoopFigures {
    long long presses = 0;
    long long motion = 0;
};

}  // namespace

int main(int argc, char** argv) {
    long long frames = 108'000;
    std::string clip_name = "click";
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--frames" && i + 1 < argc) {
            frames = std::atoll(argv[++i]);
        } else if (arg == "--clip" && i + 1 < argc) {
            clip_name = argv[++i];
        } else {
            std::fprintf(stderr, "usage: raypoint-soak [--frames N] [--clip PRESET]\n");
            return 2;
        }
    }
    unsetenv("NOTIFY_SOCKET");
    const auto& clip = test::rendered_clip(clip_name);
    const long long per_loop = static_cast<long long>(clip.size());
    const int loops = static_cast<int>((frames + per_loop - 1) / per_loop);
    if (loops < 3) {
        std::fprintf(stderr, "--frames %lld: at least three loops of %lld frames\n", frames,
                     per_loop);
        return 2;
    }

    test::DeviceModelSink sink({}, false);
    auto source =
        std::make_unique<test::ScriptedSource>(clip, std::vector<test::FaultWindow>{}, loops);
    double rss_start = 0;
    double rss_max = 0;
    LoopFigures first;
    LoopFigures last;
    LoopFigures at_loop_start;
    source->before_frame = [&](int index) {
        if (index % per_loop != 0 || index == 0) return;
        const LoopFigures done{sink.presses() - at_loop_start.presses,
                               sink.motion_events() - at_loop_start.motion};
        at_loop_start = {sink.presses(), sink.motion_events()};
        const double rss = resident_mib();
        if (index == per_loop) {
            first = done;
            rss_start = rss;  // after one loop: every buffer has its size
        }
        last = done;
        rss_max = std::max(rss_max, rss);
    };
    struct ForwardingSink final : EventSink {
        explicit ForwardingSink(test::DeviceModelSink& to) : to_(to) {}
        void emit(const raypoint::core::PointerCommand& c,
                  raypoint::core::Timestamp t) noexcept override {
            to_.emit(c, t);
        }
        void release_all(raypoint::core::Timestamp t) noexcept override { to_.release_all(t); }
        std::string_view name() const override { return to_.name(); }
        test::DeviceModelSink& to_;
    };
    DaemonParts parts;
    parts.config.core.pointer.motion.mirror = false;
    parts.source = std::move(source);
    parts.sink = std::make_unique<ForwardingSink>(sink);
    const auto started = std::chrono::steady_clock::now();
    int code = 0;
    {
        PointerDaemon daemon(std::move(parts));
        code = daemon.run();
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double rss_end = resident_mib();
    last = {sink.presses() - at_loop_start.presses, sink.motion_events() - at_loop_start.motion};
    const long long played = per_loop * loops;
    std::printf(
        "soak: %lld frames (%.1f s of frame time, %d loops of %s) in %.1f s: RSS %.2f MiB "
        "after the first loop, %.2f MiB at the end (max %.2f); presses %lld, releases "
        "%lld; first loop %lld presses, %lld motion events; last loop %lld presses, "
        "%lld motion events\n",
        played, static_cast<double>(played * test::frame_interval_us) / 1e6, loops,
        clip_name.c_str(), wall, rss_start, rss_end, std::max(rss_max, rss_end), sink.presses(),
        sink.releases(), first.presses, first.motion, last.presses, last.motion);
    int failures = 0;
    const auto check = [&](bool ok, const char* what) {
        if (!ok) {
            std::printf("FAIL: %s\n", what);
            ++failures;
        }
    };
    check(code == 0, "the daemon's exit code");
    check(rss_end - rss_start <= 1.0, "resident memory grew by more than 1 MiB");
    check(sink.presses() == sink.releases() && !sink.any_down(), "a press without its release");
    check(last.presses == first.presses, "the last loop clicks unlike the first");
    check(last.motion > 0 && first.motion > 0, "a loop without motion");
    return failures == 0 ? 0 : 1;
}
