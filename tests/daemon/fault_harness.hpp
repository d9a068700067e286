// SPDX-License-Identifier: MIT
#pragma once
// What the daemon's fault tests drive PointerDaemon::run() with: a rendered clip as a camera that
// misbehaves on cue (ScriptedSource), and an output that encodes and writes exactly as the uinput
// device does (PointerEncoder, write_batch) into a model of the kernel's key state, with writes
// that fail on cue (DeviceModelSink). The kernel's own uinput is tested in the VM; this is the
// daemon's side of every fault, frame by frame and faster than real time.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/capture/frame_source.hpp"
#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

namespace raypoint::daemon::test {

constexpr core::Timestamp frame_interval_us = 33'333;  // the clips' 30 fps

enum class Fault { none, black, saturated, frozen, flicker, capture_error };

// What the camera does from frame `first` to frame `last` (inclusive, clip frame indices).
struct FaultWindow {
    Fault fault = Fault::none;
    int first = 0;
    int last = -1;
};

// Frame i of the clip at i x frame_interval_us, through the faults of the script. A capture
// error reports `lost` once, then reopen() fails until the clip has passed the window (the clip's
// time goes on while the camera is away, as a replugged camera's does), then succeeds.
class ScriptedSource final : public FrameSource {
  public:
    // `loops`: the clip again and again, its time going on (frame i at i x frame_interval_us).
    ScriptedSource(const std::vector<cv::Mat>& clip, std::vector<FaultWindow> script,
                   int loops = 1);

    Capture next(int timeout_ms) override;
    void release() noexcept override {}
    bool reopen() override;
    const std::string& last_error() const noexcept override { return error_; }
    std::string description() const override { return "scripted clip"; }

    // Reopen attempts that fail after each capture error before one works.
    int failed_reopens = 1;
    // Runs at the start of each next() with the index of the frame about to be delivered.
    std::function<void(int)> before_frame;
    int reopen_attempts() const noexcept { return reopen_attempts_; }

  private:
    const FaultWindow* window_at(int index) const noexcept;

    const std::vector<cv::Mat>& clip_;
    std::vector<FaultWindow> script_;
    cv::Mat shown_;  // what the frame holds: the clip's frame, or the fault's
    cv::Mat last_good_;
    int index_ = 0;
    int frames_ = 0;  // in all the loops
    bool lost_ = false;
    int reopen_attempts_ = 0;
    int attempts_this_loss_ = 0;
    std::string error_;
};

// A button press or release the device model took, at the frame's timestamp.
struct KeyEvent {
    core::Timestamp at = 0;
    core::Button button = core::Button::left;
    bool pressed = false;
};

class DeviceModelSink final : public EventSink {
  public:
    // `record`: keep each key's event and each motion's time (keys(), motion_since()); a long
    // run counts only, so that the sink's own memory stays flat.
    explicit DeviceModelSink(const DeviceProfile& profile = {}, bool record = true)
        : encoder_(profile), record_(record) {}

    void emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept override;
    void release_all(core::Timestamp timestamp) noexcept override;
    std::string_view name() const override { return "device model"; }
    int last_error() const noexcept override { return last_error_; }
    long long failed_writes() const noexcept override { return failed_writes_; }

    // Every write fails with this errno (EAGAIN, ENODEV) while it is not 0.
    int fail_with = 0;

    bool any_down() const noexcept { return down_[0] || down_[1] || down_[2]; }
    const std::vector<KeyEvent>& keys() const noexcept { return keys_; }
    long long motion_events() const noexcept { return motion_events_; }
    long long presses() const noexcept { return presses_; }
    long long releases() const noexcept { return releases_; }
    // Motion events taken at or after `from`.
    long long motion_since(core::Timestamp from) const noexcept;

  private:
    void write(const EventBatch& batch, core::Timestamp timestamp) noexcept;

    PointerEncoder encoder_;
    bool record_;
    long long presses_ = 0;
    long long releases_ = 0;
    bool down_[3] = {false, false, false};  // the kernel's key state
    std::vector<KeyEvent> keys_;
    std::vector<core::Timestamp> motion_at_;
    long long motion_events_ = 0;
    int last_error_ = 0;
    long long failed_writes_ = 0;
};

// The preset's clip at 320x240 and 30 fps, rendered once a process.
const std::vector<cv::Mat>& rendered_clip(const std::string& preset);

}  // namespace raypoint::daemon::test
