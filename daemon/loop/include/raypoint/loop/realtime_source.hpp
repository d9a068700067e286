// SPDX-License-Identifier: MIT
#pragma once
// `raypoint run --input CLIP --realtime`: a clip held in memory as YUYV frames (yuyv_clip.hpp)
// or as MJPEG frames decoded when due (mjpeg_clip.hpp), delivered like a webcam delivers them.
// Frame n is due at start + n / fps on CLOCK_MONOTONIC; a timerfd armed at that instant is the
// descriptor the loop polls, as it polls a camera's, and the frame's timestamp and ready time are
// that instant, as a V4L2 buffer's timestamp is its capture time. So the loop's cost with it is the
// cost with a camera: waiting, the core on the same YUYV pixels, and the output; the capture's own
// cost (the driver, USB) is not in it.
//
// Like a camera with four buffers, at most three frames wait for a loop that fell behind; the
// older ones are dropped and counted.

#include <cstdint>
#include <string>

#include <variant>
#include "raypoint/capture/frame_source.hpp"

#include "raypoint/loop/mjpeg_clip.hpp"
#include "raypoint/loop/yuyv_clip.hpp"

namespace raypoint::daemon {

class RealtimeSource final : public FrameSource {
  public:
    // `loop`: start over after the last frame, for ever (the loop stops at --duration);
    // otherwise report CaptureStatus::ended after it. `label` names the clip in description().
    // Throws std::runtime_error when the timerfd cannot be made, std::invalid_argument for an
    // empty clip.
    RealtimeSource(YuyvClip clip, std::string label, bool loop);
    // The same with an MJPEG camera's frames: each is decoded when it is delivered; one that
    // does not decode is skipped and counted as dropped.
    RealtimeSource(MjpegClip clip, std::string label, bool loop);
    ~RealtimeSource() override;
    RealtimeSource(const RealtimeSource&) = delete;
    RealtimeSource& operator=(const RealtimeSource&) = delete;

    Capture next(int timeout_ms) override;
    int wait_fd() const noexcept override { return timer_fd_; }
    void release() noexcept override { finished_ = true; }
    bool reopen() override { return false; }
    const std::string& last_error() const noexcept override { return error_; }
    std::string description() const override;

    std::int64_t delivered() const noexcept { return delivered_; }
    std::int64_t dropped() const noexcept { return dropped_; }

  private:
    RealtimeSource(std::variant<YuyvClip, MjpegClip> clip, std::string label, bool loop);
    core::Timestamp due(std::int64_t serial) const noexcept;  // CLOCK_MONOTONIC microseconds
    void arm(core::Timestamp when) noexcept;
    // Reads the timer's expirations, so that poll() on it waits until it is armed again.
    void clear_timer() noexcept;

    // The clip's rate and length, from either kind.
    double fps() const noexcept;
    int frame_count() const noexcept;
    // f(clip) on the clip held; std::get_if, not std::visit, which may throw
    // (bad_variant_access) where this must not.
    template <typename F>
    auto on_clip(F&& f) noexcept {
        if (auto* mjpeg = std::get_if<MjpegClip>(&clip_)) return f(*mjpeg);
        return f(*std::get_if<YuyvClip>(&clip_));
    }
    template <typename F>
    auto on_clip(F&& f) const noexcept {
        if (const auto* mjpeg = std::get_if<MjpegClip>(&clip_)) return f(*mjpeg);
        return f(*std::get_if<YuyvClip>(&clip_));
    }

    std::variant<YuyvClip, MjpegClip> clip_;
    std::string label_;
    bool loop_;
    int timer_fd_ = -1;
    core::Timestamp start_ = -1;  // frame 0's due time: the first call to next()
    std::int64_t serial_ = 0;     // the next frame to deliver, counting on across loops
    std::int64_t delivered_ = 0;
    std::int64_t dropped_ = 0;
    bool finished_ = false;
    std::string error_ = "a replayed clip cannot be reopened";
};

}  // namespace raypoint::daemon
