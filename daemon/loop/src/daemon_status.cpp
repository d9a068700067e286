// SPDX-License-Identifier: MIT
// What the daemon says about itself: STATUS= a second, `ctl status`'s text, and the cost figures
// it logs at exit.
#include <cstdio>

#include "raypoint/loop/pointer_daemon.hpp"
#include "raypoint/service/log.hpp"

namespace raypoint::daemon {
namespace {

using Clock = RunStatistics::Clock;

std::string format_status(const char* format, double a, double b) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, format, a, b);
    return buffer;
}

}  // namespace

void PointerDaemon::report(Clock::time_point now) {
    if (!statistics_.update(now)) return;
    // The STATUS= line costs a few allocations a second; outside systemd it has no reader.
    if (!notifier_.enabled()) return;
    std::string state =
        camera_lost_ ? "waiting for a camera" : std::string(core::to_string(last_result_.state));
    if (paused_) state += parts_.close_when_paused ? " (paused, camera closed)" : " (paused)";
    if (output_failing_) state += " (output failing)";
    notifier_.status(state + format_status(", %.1f fps, CPU %.1f%%", statistics_.fps(),
                                           statistics_.cpu_percent()));
}

std::string PointerDaemon::status_text() const {
    std::string text = "state: " + std::string(core::to_string(last_result_.state)) + "\n";
    text += std::string("paused: ") + (paused_ ? "yes" : "no") + "\n";
    text +=
        "source: " +
        (camera_lost_ ? "waiting for a camera (" + lost_reason_ + ")"
                      : parts_.source->description() +
                            (paused_ && parts_.close_when_paused ? " (closed while paused)" : "")) +
        "\n";
    text += "sink: " + std::string(parts_.sink->name()) + "\n";
    // Writes the device refused (EAGAIN, ENODEV): a lost release is sent again (PointerEncoder),
    // but the user should know why a movement or click went missing.
    text += "output errors: " + std::to_string(parts_.sink->failed_writes());
    if (parts_.sink->failed_writes() > 0) {
        text += std::string(" (last: ") + std::strerror(parts_.sink->last_error()) + ")";
    }
    text += "\n";
    text += format_status("fps: %.1f\ncpu: %.1f%% of one core\n", statistics_.fps(),
                          statistics_.cpu_percent());
    text += "frames: " + std::to_string(statistics_.frames()) + "\n";
    text += "camera losses: " + std::to_string(lost_count_) + "\n";
    if (parts_.control && parts_.control->refused_peers() > 0) {
        text += "control clients refused (another user): " +
                std::to_string(parts_.control->refused_peers()) + "\n";
    }
    text += "instructions: " +
            (instructions_text_.empty()
                 ? "measuring (" + std::to_string(instruction_trial_.frames_recorded()) +
                       " frames so far)"
                 : instructions_text_) +
            "\n";
    text += statistics_.cost_text(Clock::now());
    if (last_result_.has_position) {
        char position[96];
        std::snprintf(position, sizeof position, "position: %.3f %.3f %.3f\n",
                      last_result_.position.x, last_result_.position.y, last_result_.position.z);
        text += position;
    }
    return text;
}

void PointerDaemon::log_cost() const {
    // One block, a line a log entry: what the run cost (run_statistics.hpp says what each
    // figure counts) and where the frames came from, which says whether capture is in it.
    log::info("cost of this run:");
    const std::string text = statistics_.cost_text(Clock::now());
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = text.find('\n', start);
        log::info("  " + text.substr(start, end - start));
        start = end == std::string::npos ? text.size() : end + 1;
    }
    log::info("  source: " + parts_.source->description());
}

}  // namespace raypoint::daemon
