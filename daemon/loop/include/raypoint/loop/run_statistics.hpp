// SPDX-License-Identifier: MIT
#pragma once
// What `raypoint ctl status`, systemd's STATUS= and the summary at exit report: frames a second
// and CPU over the last second or so, and over the whole run the daemon's cost
// (docs/performance.md): CPU time from getrusage (user + system, every thread of the process) over
// the wall time since start(), peak RSS (ru_maxrss), and the latencies from frame ready to the
// output write.

#include <sys/resource.h>

#include <chrono>
#include <string>

#include "raypoint/core/frame.hpp"
#include "raypoint/loop/latency_histogram.hpp"

namespace raypoint::daemon {

// The whole run so far.
struct RunTotals {
    double wall_seconds = 0.0;  // since start()
    double user_seconds = 0.0;  // CPU since start(), all threads
    double system_seconds = 0.0;
    double cpu_percent = 0.0;  // (user + system) / wall, of one core
    long peak_rss_kb = 0;      // ru_maxrss: the largest resident set the process ever had
    long rss_kb = 0;           // resident now (/proc/self/statm), 0 when unreadable
    long long frames = 0;
};

class RunStatistics {
  public:
    using Clock = std::chrono::steady_clock;

    RunStatistics();
    // Starts the run's totals here (after setup: opening the camera, or loading a clip, is not
    // part of the steady-state cost), and the latency histograms afresh.
    void start(Clock::time_point now) noexcept;

    void count_frame() noexcept {
        ++frames_;
        ++window_frames_;
    }
    // One written frame, times in microseconds on CLOCK_MONOTONIC: `ready` when the frame was
    // ready (the V4L2 buffer's timestamp, a replayed frame's due time; negative: unknown),
    // `handed` when the source handed it to the loop, `written` after the sink's write returned.
    void record_latency(core::Timestamp ready, core::Timestamp handed,
                        core::Timestamp written) noexcept {
        if (ready >= 0) ready_to_write_.record(written - ready);
        handed_to_write_.record(written - handed);
    }
    // Recomputes fps and CPU when at least a second has passed; returns true when it did.
    bool update(Clock::time_point now) noexcept;

    double fps() const noexcept { return fps_; }
    double cpu_percent() const noexcept { return cpu_percent_; }  // of one core
    long long frames() const noexcept { return frames_; }
    const LatencyHistogram& ready_to_write() const noexcept { return ready_to_write_; }
    const LatencyHistogram& handed_to_write() const noexcept { return handed_to_write_; }

    RunTotals totals(Clock::time_point now) const noexcept;
    // The run's cost as lines "name: value\n" (cpu, rss, latency), for `ctl status` and the
    // summary at exit.
    std::string cost_text(Clock::time_point now) const;

  private:
    static double cpu_seconds() noexcept;

    Clock::time_point window_start_;
    double window_cpu_ = 0.0;
    long long window_frames_ = 0;
    long long frames_ = 0;
    double fps_ = 0.0;
    double cpu_percent_ = 0.0;

    Clock::time_point run_start_;
    rusage run_start_usage_{};
    LatencyHistogram ready_to_write_;
    LatencyHistogram handed_to_write_;
};

// CLOCK_MONOTONIC in microseconds: the clock of V4L2 buffer timestamps and of steady_clock.
core::Timestamp monotonic_now_us() noexcept;

}  // namespace raypoint::daemon
