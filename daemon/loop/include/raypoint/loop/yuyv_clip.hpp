// SPDX-License-Identifier: MIT
#pragma once
// Frames as a YUYV webcam delivers them (V4L2_PIX_FMT_YUYV, BT.601 limited range, rows packed),
// held in memory: what `raypoint run --realtime` replays, so that the daemon's measured cost is
// the cost with a camera (wait, process, output) and not a video decoder's.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "raypoint/core/frame.hpp"

namespace raypoint::daemon {

class YuyvClip {
  public:
    // An empty clip of `size` frames (the width rounded down to even: two pixels share U and V)
    // at `fps` frames a second.
    YuyvClip(cv::Size size, double fps);

    // Converts a CV_8UC3 BGR frame of at least size() and appends it (the extra column of an
    // odd width is dropped). Throws std::invalid_argument for another type or a smaller frame.
    void append(const cv::Mat& bgr);
    // Room for `frames` frames in all, so that loading a clip of known length copies nothing.
    void reserve(int frames) { bytes_.reserve(frame_bytes() * std::size_t(frames)); }

    cv::Size size() const noexcept { return size_; }
    double fps() const noexcept { return fps_; }
    int frame_count() const noexcept { return static_cast<int>(bytes_.size() / frame_bytes()); }
    std::size_t frame_bytes() const noexcept { return std::size_t(stride()) * size_.height; }
    std::size_t memory_bytes() const noexcept { return bytes_.size(); }
    int stride() const noexcept { return size_.width * 2; }

    // Frame `index` (0 <= index < frame_count()) as the core reads a camera's buffer.
    core::FrameView view(int index, core::Timestamp timestamp) const noexcept;

  private:
    cv::Size size_;
    double fps_;
    std::vector<std::uint8_t> bytes_;  // frame after frame, each stride() * height bytes
    cv::Mat yuv_;                      // append()'s conversion buffer, reused
};

}  // namespace raypoint::daemon
