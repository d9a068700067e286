// SPDX-License-Identifier: MIT
#pragma once
// The loop of `raypoint run`: frames from a source through the tracker and the pointer to an
// event sink, with the camera's loss and return, pause/resume/recenter/status over the control
// socket, SIGHUP reload, SIGINT/SIGTERM exit, and systemd's notify protocol. Every pressed
// button is released on loss, pause, reload and exit.

#include <signal.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "raypoint/capture/frame_source.hpp"
#include "raypoint/config/config.hpp"
#include "raypoint/control/control_socket.hpp"
#include "raypoint/core/instruction_trial.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/loop/run_statistics.hpp"
#include "raypoint/output/event_sink.hpp"
#include "raypoint/service/sd_notify.hpp"

namespace raypoint::daemon {

// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread and every thread it starts later;
// the daemon reads them from a signalfd. Call before opening the camera or a video.
sigset_t block_daemon_signals();

struct DaemonParts {
    config::Config config;
    std::unique_ptr<FrameSource> source;
    std::unique_ptr<EventSink> sink;
    std::unique_ptr<ControlServer> control;  // null: no control socket
    bool exit_when_lost = false;             // a recorded video: exit when it fails, not reopen
    // The source could not be opened at start (no camera plugged in): the daemon starts anyway,
    // says "waiting for a camera" and opens it when it appears.
    bool start_closed = false;
    // A live camera: paused means closed (its light off, free for a video call), reopened on
    // resume. A recorded source keeps its place instead.
    bool close_when_paused = false;
    // --duration: stop after this long (measuring the daemon's cost over a fixed time).
    std::optional<std::chrono::milliseconds> duration;
    // SIGHUP: the new configuration, or throws config::ConfigError to keep the running one.
    std::function<config::Config()> reload;
};

class PointerDaemon {
  public:
    explicit PointerDaemon(DaemonParts parts);
    ~PointerDaemon();
    PointerDaemon(const PointerDaemon&) = delete;
    PointerDaemon& operator=(const PointerDaemon&) = delete;

    // Runs until SIGINT or SIGTERM (or the end of a recorded input, or the duration). Prints the
    // run's cost (run_statistics.hpp) to stderr at the end. Returns the exit code.
    int run();

  private:
    // What woke wait_for_events(): bits of these.
    enum Ready : unsigned { source_ready = 1U, signal_ready = 2U, control_ready = 4U };

    // Sleeps in one poll(2) on the signalfd, the control socket and `source_fd` (if >= 0) until
    // one is readable or `deadline`. The loop's only sleep: no wake-up without work.
    unsigned wait_for_events(int source_fd,
                             RunStatistics::Clock::time_point deadline) const noexcept;
    void on_frame(const Capture& capture);
    // The instruction sets of a new tracker: measured over its first frames (INITIALIZING's,
    // which it does nothing useful with) unless [tracking] instructions names one.
    void start_instruction_trial();
    core::FrameResult process_in_trial(const core::FrameView& frame) noexcept;
    void apply_instruction_choice();
    void on_lost(const std::string& reason);
    void pause();
    void resume();
    void check_output();    // after each emit: log the start and the end of failing writes
    bool handle_signals();  // false: stop
    void handle_control();
    void reload();
    void release_buttons();
    void report(RunStatistics::Clock::time_point now);
    std::string status_text() const;
    void log_cost() const;

    DaemonParts parts_;
    std::unique_ptr<core::Tracker> tracker_;
    std::optional<core::PointerController> pointer_;  // made at the first frame (its aspect)
    core::InstructionTrial instruction_trial_{core::InstructionSet::scalar};
    std::string instructions_text_;  // the choice, for `ctl status`; empty while measuring
    SdNotifier notifier_;
    RunStatistics statistics_;
    int signal_fd_ = -1;
    bool paused_ = false;
    bool camera_lost_ = false;
    bool input_ended_ = false;  // a recorded source's CaptureStatus::ended: the run is over
    std::string lost_reason_;
    RunStatistics::Clock::time_point next_reopen_{};
    RunStatistics::Clock::time_point stop_at_ = RunStatistics::Clock::time_point::max();
    RunStatistics::Clock::time_point last_frame_at_{};  // the stall timeout's start
    core::Timestamp last_timestamp_ = 0;
    core::FrameResult last_result_{};
    cv::Point2d recenter_offset_{0.0, 0.0};
    long long lost_count_ = 0;
    long long failed_writes_seen_ = 0;
    bool output_failing_ = false;  // the last frame's write failed
};

}  // namespace raypoint::daemon
