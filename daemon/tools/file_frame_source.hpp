// SPDX-License-Identifier: MIT
#pragma once
// A recorded video as a FrameSource (`raypoint run --input FILE`): the same loop as a live
// camera, for tests and for replaying a user's recording. Paced at the video's own rate by
// default; unpaced, it runs as fast as the core does.

#include <chrono>
#include <optional>
#include <string>

#include "raypoint/capture/frame_source.hpp"
#include "video_source.hpp"

namespace raypoint::daemon {

class FileFrameSource final : public FrameSource {
  public:
    // Throws InputError (video_source.hpp) when the file cannot be read as video.
    FileFrameSource(const std::string& path, bool paced);

    Capture next(int timeout_ms) override;
    void release() noexcept override { finished_ = true; }
    bool reopen() override { return false; }
    const std::string& last_error() const noexcept override { return error_; }
    std::string description() const override;

    // The video has no more frames: `next()` reports CaptureStatus::ended.
    bool finished() const noexcept { return finished_; }
    cv::Size size() const noexcept { return video_.size(); }

  private:
    VideoSource video_;
    bool paced_;
    bool finished_ = false;
    std::string error_ = "a recorded video cannot be reopened";
    std::optional<DecodedFrame> current_;
    std::optional<std::chrono::steady_clock::time_point> started_;
};

}  // namespace raypoint::daemon
