#include "pointer_daemon.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "log.hpp"

namespace raypoint::daemon {
namespace {

using Clock = RunStatistics::Clock;

// The camera comes back within 2 s of being plugged in again (the promise).
constexpr auto reopen_interval = std::chrono::milliseconds(500);
constexpr int frame_timeout_ms = 100;
// A camera that stops delivering without an error (a driver that wedges, a v4l2loopback whose
// writer quit) is lost too: buttons up, reported, reopened like an unplugged one. 2 s is ten
// frames at the slowest low-light rate (5 fps) and a UVC camera's slow first frame.
constexpr auto stall_timeout = std::chrono::seconds(2);

std::string format_status(const char* format, double a, double b) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, format, a, b);
    return buffer;
}

}  // namespace

sigset_t block_daemon_signals() {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGHUP);
    // Blocked in every thread (threads inherit the mask, so this comes before any decoder or
    // library starts one) and read from a descriptor: a signal is handled between frames, never
    // in the middle of writing an event.
    if (pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) {
        throw std::runtime_error(std::string("pthread_sigmask: ") + std::strerror(errno));
    }
    return signals;
}

PointerDaemon::PointerDaemon(DaemonParts parts)
    : parts_(std::move(parts)), tracker_(std::make_unique<core::Tracker>(parts_.config.core)) {
    const sigset_t signals = block_daemon_signals();
    signal_fd_ = signalfd(-1, &signals, SFD_NONBLOCK | SFD_CLOEXEC);
    if (signal_fd_ < 0) throw std::runtime_error(std::string("signalfd: ") + std::strerror(errno));
}

PointerDaemon::~PointerDaemon() {
    if (signal_fd_ >= 0) close(signal_fd_);
}

int PointerDaemon::run() {
    log::info("capturing from " + parts_.source->description() + ", events to " +
              std::string(parts_.sink->name()));
    notifier_.ready();
    notifier_.status("initializing");
    last_frame_at_ = Clock::now();
    for (;;) {
        if (!handle_signals()) break;
        handle_control();
        const auto now = Clock::now();
        if (camera_lost_) {
            if (parts_.stop_at_end_of_input) break;
            // Alive and handling it: keep the watchdog fed while the camera is away.
            if (notifier_.watchdog_due(now)) notifier_.pet(now);
            if (now >= next_reopen_) {
                next_reopen_ = now + reopen_interval;
                if (parts_.source->reopen()) {
                    camera_lost_ = false;
                    last_frame_at_ = now;
                    log::info("camera back: " + parts_.source->description());
                }
            }
            usleep(50'000);
            continue;
        }
        const Capture capture = parts_.source->next(frame_timeout_ms);
        switch (capture.status) {
            case CaptureStatus::frame:
                on_frame(capture.frame);
                last_frame_at_ = now;
                // Only frames feed the watchdog (and the lost camera's retries): a loop stuck in
                // a driver call gets the service restarted.
                if (notifier_.watchdog_due(now)) notifier_.pet(now);
                break;
            case CaptureStatus::timeout:
                if (now - last_frame_at_ >= stall_timeout) on_lost("no frame for 2 s");
                break;
            case CaptureStatus::lost:
                on_lost(capture.reason);
                break;
        }
        report(Clock::now());
    }
    release_buttons();
    notifier_.stopping();
    log::info("stopped after " + std::to_string(statistics_.frames()) + " frames");
    return 0;
}

void PointerDaemon::on_frame(const core::FrameView& frame) {
    core::FrameResult result = tracker_->process(frame);
    last_timestamp_ = frame.timestamp;
    last_result_ = result;
    statistics_.count_frame();
    if (!pointer_) {
        pointer_.emplace(parts_.config.core.pointer,
                         static_cast<double>(frame.width) / static_cast<double>(frame.height));
    }
    if (paused_) return;
    // `recenter`: the hand's place at that moment is the middle of the view from then on.
    result.position.x += recenter_offset_.x;
    result.position.y += recenter_offset_.y;
    result.centroid += recenter_offset_;
    parts_.sink->emit(pointer_->update(result), frame.timestamp);
}

void PointerDaemon::on_lost(const std::string& reason) {
    release_buttons();
    if (reason == "end of input") {
        camera_lost_ = true;
        return;
    }
    ++lost_count_;
    camera_lost_ = true;
    lost_reason_ = reason;
    parts_.source->release();
    next_reopen_ = Clock::now() + reopen_interval;
    log::warning("camera lost: " + reason + "; retrying every 0.5 s");
    notifier_.status("camera lost: " + reason);
}

void PointerDaemon::release_buttons() {
    if (pointer_) parts_.sink->emit(pointer_->release_all(), last_timestamp_);
    parts_.sink->release_all(last_timestamp_);
}

bool PointerDaemon::handle_signals() {
    signalfd_siginfo info{};
    while (read(signal_fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
        switch (info.ssi_signo) {
            case SIGHUP:
                reload();
                break;
            case SIGINT:
            case SIGTERM:
                log::info(std::string("stopping on ") +
                          strsignal(static_cast<int>(info.ssi_signo)));
                return false;
            default:
                break;
        }
    }
    return true;
}

void PointerDaemon::reload() {
    if (!parts_.reload) return;
    try {
        config::Config fresh = parts_.reload();
        release_buttons();
        parts_.config = fresh;
        tracker_ = std::make_unique<core::Tracker>(parts_.config.core);
        pointer_.reset();
        log::info("configuration reloaded");
    } catch (const std::exception& e) {
        log::error(std::string("reload failed, keeping the running configuration: ") + e.what());
    }
}

void PointerDaemon::handle_control() {
    if (!parts_.control) return;
    while (const auto command = parts_.control->next_request()) {
        switch (*command) {
            case ControlCommand::pause:
                if (!paused_) release_buttons();
                paused_ = true;
                parts_.control->reply("paused\n");
                break;
            case ControlCommand::resume:
                paused_ = false;
                parts_.control->reply("resumed\n");
                break;
            case ControlCommand::recenter:
                if (last_result_.has_position) {
                    recenter_offset_ = {0.5 - last_result_.position.x,
                                        0.5 - last_result_.position.y};
                    parts_.control->reply("recentered\n");
                } else {
                    parts_.control->reply("not tracking: nothing to recenter on\n");
                }
                break;
            case ControlCommand::status:
                parts_.control->reply(status_text());
                break;
        }
    }
}

void PointerDaemon::report(Clock::time_point now) {
    if (!statistics_.update(now)) return;
    std::string state =
        camera_lost_ ? "camera lost" : std::string(core::to_string(last_result_.state));
    if (paused_) state += " (paused)";
    notifier_.status(state + format_status(", %.1f fps, CPU %.1f%%", statistics_.fps(),
                                           statistics_.cpu_percent()));
}

std::string PointerDaemon::status_text() const {
    std::string text = "state: " + std::string(core::to_string(last_result_.state)) + "\n";
    text += std::string("paused: ") + (paused_ ? "yes" : "no") + "\n";
    text += "source: " + parts_.source->description() +
            (camera_lost_ ? " (lost: " + lost_reason_ + ")" : "") + "\n";
    text += "sink: " + std::string(parts_.sink->name()) + "\n";
    text += format_status("fps: %.1f\ncpu: %.1f%% of one core\n", statistics_.fps(),
                          statistics_.cpu_percent());
    text += "frames: " + std::to_string(statistics_.frames()) + "\n";
    text += "camera losses: " + std::to_string(lost_count_) + "\n";
    if (last_result_.has_position) {
        char position[96];
        std::snprintf(position, sizeof position, "position: %.3f %.3f %.3f\n",
                      last_result_.position.x, last_result_.position.y, last_result_.position.z);
        text += position;
    }
    return text;
}

}  // namespace raypoint::daemon
