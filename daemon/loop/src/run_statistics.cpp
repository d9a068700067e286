// SPDX-License-Identifier: MIT
#include "raypoint/loop/run_statistics.hpp"

#include <time.h>
#include <unistd.h>

#include <cstdio>

namespace raypoint::daemon {
namespace {

double seconds(const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
}

// The resident set now, from /proc/self/statm (pages); 0 when it cannot be read.
long resident_kb() noexcept {
    std::FILE* file = std::fopen("/proc/self/statm", "re");
    if (file == nullptr) return 0;
    long size = 0;
    long resident = 0;
    const int read = std::fscanf(file, "%ld %ld", &size, &resident);
    std::fclose(file);
    if (read != 2) return 0;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace

core::Timestamp monotonic_now_us() noexcept {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return core::seconds_to_us(std::int64_t{now.tv_sec}) + now.tv_nsec / 1000;
}

RunStatistics::RunStatistics() : window_start_(Clock::now()), window_cpu_(cpu_seconds()) {
    start(window_start_);
}

void RunStatistics::start(Clock::time_point now) noexcept {
    run_start_ = now;
    getrusage(RUSAGE_SELF, &run_start_usage_);
    frames_ = 0;
    ready_to_write_.clear();
    handed_to_write_.clear();
}

double RunStatistics::cpu_seconds() noexcept {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
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

RunTotals RunStatistics::totals(Clock::time_point now) const noexcept {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    RunTotals totals;
    totals.wall_seconds = std::chrono::duration<double>(now - run_start_).count();
    totals.user_seconds = seconds(usage.ru_utime) - seconds(run_start_usage_.ru_utime);
    totals.system_seconds = seconds(usage.ru_stime) - seconds(run_start_usage_.ru_stime);
    if (totals.wall_seconds > 0.0) {
        totals.cpu_percent =
            100.0 * (totals.user_seconds + totals.system_seconds) / totals.wall_seconds;
    }
    totals.peak_rss_kb = usage.ru_maxrss;  // Linux: kilobytes
    totals.rss_kb = resident_kb();
    totals.frames = frames_;
    return totals;
}

std::string RunStatistics::cost_text(Clock::time_point now) const {
    const RunTotals run = totals(now);
    char text[640];
    const auto latency = [](const LatencyHistogram& h, char* out, std::size_t size) {
        if (h.count() == 0) {
            std::snprintf(out, size, "none written yet");
            return;
        }
        std::snprintf(out, size, "median %lld us, p99 %lld us, max %lld us (%lld frames)",
                      static_cast<long long>(h.quantile(0.5)),
                      static_cast<long long>(h.quantile(0.99)), static_cast<long long>(h.max()),
                      static_cast<long long>(h.count()));
    };
    char ready[128];
    char handed[128];
    latency(ready_to_write_, ready, sizeof ready);
    latency(handed_to_write_, handed, sizeof handed);
    std::snprintf(text, sizeof text,
                  "run: %.1f s, %lld frames, %.1f fps\n"
                  "run cpu: %.2f%% of one core (user %.2f s + system %.2f s)\n"
                  "peak rss: %.1f MiB (ru_maxrss), %.1f MiB resident now\n"
                  "latency ready to write: %s\n"
                  "latency handed to write: %s\n",
                  run.wall_seconds, run.frames,
                  run.wall_seconds > 0.0 ? static_cast<double>(run.frames) / run.wall_seconds : 0.0,
                  run.cpu_percent, run.user_seconds, run.system_seconds,
                  static_cast<double>(run.peak_rss_kb) / 1024.0,
                  static_cast<double>(run.rss_kb) / 1024.0, ready, handed);
    return text;
}

}  // namespace raypoint::daemon
