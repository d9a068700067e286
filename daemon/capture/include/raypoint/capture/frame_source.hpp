// SPDX-License-Identifier: MIT
#pragma once
// A live source of frames for the tracking loop: a camera, or anything that acts like one.

#include <string>

#include "raypoint/core/frame.hpp"

namespace raypoint::daemon {

// What next() got. Per frame, nothing throws: a lost camera is a status the loop handles
// (release the buttons, reopen() it at intervals), not an exception unwinding through it.
enum class CaptureStatus {
    frame,    // `Capture::frame` holds a new frame
    timeout,  // no frame within the timeout (the camera is slow, covered, or stalled)
    lost,     // the device failed or disappeared (ENODEV, EIO, POLLERR); call reopen()
    ended,    // a recorded source has delivered its last frame; a camera never ends
};

struct Capture {
    CaptureStatus status = CaptureStatus::timeout;
    // Valid when status == frame, until the next call to next(), release() or reopen(): the
    // pixels may be the driver's own buffer, handed back to it on the next call.
    core::FrameView frame;
    std::string reason;  // when lost: the failing call and errno text, for the log
    // When the frame was ready, microseconds on CLOCK_MONOTONIC (a V4L2 buffer's timestamp, a
    // replayed frame's due time), for the latency to the output; negative when unknown.
    core::Timestamp ready = -1;
};

// A recorded source's last word, for every call after its last frame.
inline Capture end_of_input_capture() {
    return Capture{CaptureStatus::ended, {}, {}};
}

class FrameSource {
  public:
    virtual ~FrameSource() = default;

    // Waits up to `timeout_ms` milliseconds (>= 0; 0 only takes a frame already there) for the
    // next frame. Frame timestamps are in
    // microseconds on CLOCK_MONOTONIC, increasing.
    virtual Capture next(int timeout_ms) = 0;

    // A descriptor that polls readable (POLLIN, or POLLERR when the device fails) when next(0)
    // has something to report, so the loop can wait for frames, signals and control requests in
    // one poll(2). -1: the source has none; the loop calls next() with a timeout instead.
    virtual int wait_fd() const noexcept { return -1; }

    // Gives the device back (stops streaming, frees buffers, closes it); next() then reports
    // lost until reopen(). Safe to call twice.
    virtual void release() noexcept = 0;

    // Tries once to open and start the source again with the same settings. False while it
    // cannot (last_error() says why); the caller decides how often to retry.
    virtual bool reopen() = 0;

    // Why the last reopen() failed, or empty.
    virtual const std::string& last_error() const noexcept = 0;

    // One line for status output: which device, what mode, what was locked.
    virtual std::string description() const = 0;
};

}  // namespace raypoint::daemon
