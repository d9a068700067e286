// SPDX-License-Identifier: MIT
#include "raypoint/loop/pointer_daemon.hpp"

#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "raypoint/loop/instruction_report.hpp"
#include "raypoint/service/log.hpp"

namespace raypoint::daemon {
namespace {

using Clock = RunStatistics::Clock;

// The camera comes back within 2 s of being plugged in again (docs/design.md, "Losing and finding
// the camera").
constexpr auto reopen_interval = std::chrono::milliseconds(500);
constexpr int frame_timeout_ms = 100;
// Without frames the loop still wakes once a second, so that STATUS= and `ctl status` show the
// frame rate falling to 0 when a camera stalls.
constexpr auto idle_wake = std::chrono::seconds(1);
// A camera that stops delivering without an error (a driver that wedges, a v4l2loopback whose
// writer quit) is lost too: buttons up, reported, reopened like an unplugged one. 2 s is ten
// frames at the slowest low-light rate (5 fps) and a UVC camera's slow first frame.
constexpr auto stall_timeout = std::chrono::seconds(2);

// "2 s", "0.5 s": a duration as the log states it, from the constant itself.
std::string seconds_text(std::chrono::duration<double> duration) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g s", duration.count());
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
    log::info((parts_.start_closed ? std::string("waiting for a camera")
                                   : "capturing from " + parts_.source->description()) +
              ", events to " + std::string(parts_.sink->name()));
    // READY even without a camera: the service is up and waiting for one, which a restart loop
    // would not be (it would spin below the start-rate limit as long as the camera is away).
    notifier_.ready();
    notifier_.status("initializing");
    if (parts_.start_closed) {
        camera_lost_ = true;
        lost_reason_ = parts_.source->last_error();
        next_reopen_ = Clock::now() + reopen_interval;
        notifier_.status("waiting for a camera");
    }
    start_instruction_trial();
    const auto started = Clock::now();
    statistics_.start(started);
    if (parts_.duration) stop_at_ = started + *parts_.duration;
    last_frame_at_ = started;
    unsigned ready = signal_ready | control_ready;  // both looked at before the first wait
    for (;;) {
        if ((ready & signal_ready) != 0 && !handle_signals()) break;
        if ((ready & control_ready) != 0) handle_control();
        const auto now = Clock::now();
        if (now >= stop_at_) {
            log::info("stopping: --duration reached");
            break;
        }
        if (input_ended_) break;
        if (paused_ && parts_.close_when_paused) {
            // The camera is closed: nothing to read, only signals, requests and the watchdog.
            if (notifier_.watchdog_due(now)) notifier_.pet(now);
            ready = wait_for_events(-1, std::min(now + idle_wake, stop_at_));
            report(Clock::now());
            continue;
        }
        if (camera_lost_) {
            if (parts_.exit_when_lost) break;
            // Alive and handling it: keep the watchdog fed while the camera is away.
            if (notifier_.watchdog_due(now)) notifier_.pet(now);
            if (now >= next_reopen_) {
                next_reopen_ = now + reopen_interval;
                if (parts_.source->reopen()) {
                    camera_lost_ = false;
                    last_frame_at_ = Clock::now();
                    log::info((lost_count_ > 0 ? "camera back: " : "camera found: ") +
                              parts_.source->description());
                } else {
                    lost_reason_ = parts_.source->last_error();
                }
            }
            ready = camera_lost_ ? wait_for_events(-1, std::min(next_reopen_, stop_at_))
                                 : signal_ready | control_ready;
            continue;
        }
        Capture capture;
        if (const int fd = parts_.source->wait_fd(); fd >= 0) {
            // Woken at the stall timeout itself, not up to idle_wake after it: the watchdog's
            // budget below counts on the loss being declared on time.
            const auto wake = std::min(now + idle_wake, last_frame_at_ + stall_timeout);
            ready = wait_for_events(fd, std::min(wake, stop_at_));
            if ((ready & source_ready) != 0) capture = parts_.source->next(0);
        } else {
            // A source without a descriptor (a decoded video) waits inside next(); signals and
            // requests are looked at between its frames.
            ready = signal_ready | control_ready;
            capture = parts_.source->next(frame_timeout_ms);
        }
        switch (capture.status) {
            case CaptureStatus::frame:
                on_frame(capture);
                last_frame_at_ = Clock::now();
                // Only a turning loop feeds the watchdog (frames, a wait that timed out, the
                // lost camera's retries): a loop stuck in a driver call gets the service
                // restarted.
                if (notifier_.watchdog_due(now)) notifier_.pet(now);
                break;
            case CaptureStatus::timeout:
                // The wait returned by itself, so the loop is not stuck: it is timing a stall.
                // Without this pet, the last one (up to 2.5 s before the last frame) plus the
                // 2 s stall exceeded WatchdogSec=5 on a slow machine, and systemd killed a
                // daemon that was about to report the camera lost.
                if (notifier_.watchdog_due(now)) notifier_.pet(now);
                if (Clock::now() - last_frame_at_ >= stall_timeout) {
                    on_lost("no frame for " + seconds_text(stall_timeout));
                }
                break;
            case CaptureStatus::lost:
                on_lost(capture.reason);
                break;
            case CaptureStatus::ended:
                release_buttons();
                input_ended_ = true;
                break;
        }
        report(Clock::now());
    }
    release_buttons();
    notifier_.stopping();
    log::info("stopped after " + std::to_string(statistics_.frames()) + " frames");
    log_cost();
    return 0;
}

unsigned PointerDaemon::wait_for_events(int source_fd, Clock::time_point deadline) const noexcept {
    std::array<pollfd, 3> fds{};
    std::size_t count = 0;
    fds[count++] = pollfd{signal_fd_, POLLIN, 0};
    const std::size_t control = parts_.control ? count++ : fds.size();
    if (control < fds.size()) fds[control] = pollfd{parts_.control->fd(), POLLIN, 0};
    const std::size_t source = source_fd >= 0 ? count++ : fds.size();
    if (source < fds.size()) fds[source] = pollfd{source_fd, POLLIN, 0};
    // Rounded up: woken before the deadline, the loop would only go back to sleep.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    const auto timeout_ms = static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(
        left.count(), 0, std::numeric_limits<int>::max()));
    if (poll(fds.data(), count, timeout_ms) <= 0) return 0;  // the deadline, or EINTR
    unsigned ready = 0;
    // Any event counts: POLLERR or POLLHUP from a camera is its loss, for next() to report.
    if (fds[0].revents != 0) ready |= signal_ready;
    if (control < fds.size() && fds[control].revents != 0) ready |= control_ready;
    if (source < fds.size() && fds[source].revents != 0) ready |= source_ready;
    return ready;
}

void PointerDaemon::on_frame(const Capture& capture) {
    const core::Timestamp handed = monotonic_now_us();
    const core::FrameView& frame = capture.frame;
    core::FrameResult result =
        instruction_trial_.done() ? tracker_->process(frame) : process_in_trial(frame);
    last_timestamp_ = frame.timestamp;
    last_result_ = result;
    statistics_.count_frame();
    if (!pointer_) {
        pointer_.emplace(parts_.config.core.pointer,
                         static_cast<double>(frame.width) / static_cast<double>(frame.height),
                         parts_.config.core.output);
    }
    if (paused_) return;
    // `recenter`: the hand's place at that moment is the middle of the view from then on.
    result.position.x += recenter_offset_.x;
    result.position.y += recenter_offset_.y;
    result.centroid += recenter_offset_;
    parts_.sink->emit(pointer_->update(result), frame.timestamp);
    // After the write returned: uinput's write(2) of the events, the file sink's fflush.
    statistics_.record_latency(capture.ready, handed, monotonic_now_us());
    check_output();
}

void PointerDaemon::check_output() {
    // Logged when failures start and when they stop, not every frame (logging allocates).
    const long long failed = parts_.sink->failed_writes();
    const bool failing = failed != failed_writes_seen_;
    failed_writes_seen_ = failed;
    if (failing == output_failing_) return;
    output_failing_ = failing;
    if (failing) {
        log::warning(std::string("output: a write to ") + std::string(parts_.sink->name()) +
                     " failed: " + std::strerror(parts_.sink->last_error()) +
                     "; a lost button release is sent again");
    } else {
        log::info("output: writes no longer failing");
    }
}

void PointerDaemon::start_instruction_trial() {
    const auto forced = config::forced_instruction_set(parts_.config.instructions);
    const core::InstructionSet best = core::best_instruction_set();
    if (forced && *forced > best) {
        log::warning("[tracking] instructions = " + std::string(core::to_string(*forced)) +
                     ": this CPU runs " + std::string(core::to_string(best)) + " at most; using " +
                     std::string(core::to_string(best)));
    }
    instruction_trial_ = core::InstructionTrial(best, forced);
    instructions_text_.clear();
    if (instruction_trial_.done()) apply_instruction_choice();
}

core::FrameResult PointerDaemon::process_in_trial(const core::FrameView& frame) noexcept {
    const core::FrameResult result = daemon::process_in_trial(*tracker_, instruction_trial_, frame);
    if (instruction_trial_.done()) {
        // Once per trial; logging allocates, which the steady state never reaches.
        try {
            apply_instruction_choice();
        } catch (...) {
            tracker_->set_instructions(instruction_trial_.chosen());
        }
    }
    return result;
}

void PointerDaemon::apply_instruction_choice() {
    tracker_->set_instructions(instruction_trial_.chosen());
    const bool forced = config::forced_instruction_set(parts_.config.instructions).has_value();
    instructions_text_ = describe_trial(instruction_trial_, forced);
    log::info("instruction sets: " + instructions_text_);
}

void PointerDaemon::on_lost(const std::string& reason) {
    release_buttons();
    ++lost_count_;
    camera_lost_ = true;
    lost_reason_ = reason;
    parts_.source->release();
    next_reopen_ = Clock::now() + reopen_interval;
    log::warning("camera lost: " + reason + "; retrying every " + seconds_text(reopen_interval));
    notifier_.status("camera lost: " + reason);
}

void PointerDaemon::pause() {
    if (paused_) return;
    release_buttons();
    paused_ = true;
    if (parts_.close_when_paused && !camera_lost_) {
        parts_.source->release();
        log::info("paused: camera closed");
    }
}

void PointerDaemon::resume() {
    if (!paused_) return;
    paused_ = false;
    if (!parts_.close_when_paused || camera_lost_) return;
    if (parts_.source->reopen()) {
        last_frame_at_ = Clock::now();
        log::info("resumed: camera open again: " + parts_.source->description());
    } else {
        // Unplugged while paused: wait for it as for a lost camera.
        ++lost_count_;
        camera_lost_ = true;
        lost_reason_ = parts_.source->last_error();
        next_reopen_ = Clock::now() + reopen_interval;
        log::warning("resumed, but the camera does not open: " + lost_reason_ +
                     "; waiting for a camera");
    }
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
        // A new working size or edge source can change which sets are cheapest.
        start_instruction_trial();
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
                pause();
                parts_.control->reply("paused\n");
                break;
            case ControlCommand::resume:
                resume();
                parts_.control->reply("resumed\n");
                break;
            case ControlCommand::toggle:
                if (paused_) {
                    resume();
                    parts_.control->reply("resumed\n");
                } else {
                    pause();
                    parts_.control->reply("paused\n");
                }
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

}  // namespace raypoint::daemon
