#pragma once
// What `raypoint ctl status` and systemd's STATUS= report: frames a second and the CPU the
// daemon uses, over the last second or so.

#include <sys/resource.h>

#include <chrono>
#include <string>

namespace raypoint::daemon {

class RunStatistics {
  public:
    using Clock = std::chrono::steady_clock;

    RunStatistics();
    void count_frame() noexcept {
        ++frames_;
        ++window_frames_;
    }
    // Recomputes fps and CPU when at least a second has passed; returns true when it did.
    bool update(Clock::time_point now) noexcept;

    double fps() const noexcept { return fps_; }
    double cpu_percent() const noexcept { return cpu_percent_; }  // of one core
    long long frames() const noexcept { return frames_; }

  private:
    static double cpu_seconds() noexcept;

    Clock::time_point window_start_;
    double window_cpu_ = 0.0;
    long long window_frames_ = 0;
    long long frames_ = 0;
    double fps_ = 0.0;
    double cpu_percent_ = 0.0;
};

}  // namespace raypoint::daemon
