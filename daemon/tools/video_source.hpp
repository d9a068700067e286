// SPDX-License-Identifier: MIT
#pragma once
// Decoded frames of a recorded video or image sequence, with their timestamps. Offline input
// only: the live camera (V4L2) is a different source.

#include <optional>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "raypoint/core/frame.hpp"

namespace raypoint::daemon {

struct DecodedFrame {
    cv::Mat bgr;
    core::Timestamp timestamp = 0;  // microseconds from the first frame
};

class VideoSource {
  public:
    // `path` is a file or a printf-style image sequence ("frames/%04d.png"). `fps` > 0 overrides
    // the container's timestamps with frame / fps. Throws InputError.
    VideoSource(const std::string& path, double fps);

    // The next frame, or nothing at the end. Throws InputError when the container promised
    // more frames than could be decoded (a truncated file).
    std::optional<DecodedFrame> next();

    double fps() const noexcept { return fps_; }
    int frame_count() const noexcept { return frame_count_; }  // 0 when unknown
    cv::Size size() const noexcept { return size_; }
    const std::string& path() const noexcept { return path_; }

  private:
    std::string path_;
    cv::VideoCapture capture_;
    double fps_ = 30.0;
    bool fixed_rate_ = false;
    int frame_count_ = 0;
    cv::Size size_;
    int index_ = 0;
    core::Timestamp last_ = -1;
};

}  // namespace raypoint::daemon
