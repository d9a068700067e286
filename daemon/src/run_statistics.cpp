#include "run_statistics.hpp"

namespace raypoint::daemon {

RunStatistics::RunStatistics() : window_start_(Clock::now()), window_cpu_(cpu_seconds()) {}

double RunStatistics::cpu_seconds() noexcept {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

bool RunStatistics::update(Clock::time_point now) noexcept {
    const double elapsed = std::chrono::duration<double>(now - window_start_).count();
    if (elapsed < 1.0) return false;
    const double cpu = cpu_seconds();
    fps_ = static_cast<double>(window_frames_) / elapsed;
    cpu_percent_ = 100.0 * (cpu - window_cpu_) / elapsed;
    window_start_ = now;
    window_cpu_ = cpu;
    window_frames_ = 0;
    return true;
}

}  // namespace raypoint::daemon
