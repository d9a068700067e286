// SPDX-License-Identifier: MIT
#pragma once
// Frames as an MJPEG webcam delivers them, held in memory as compressed JPEGs and decoded when
// they are delivered, as the camera path decodes a V4L2 buffer (JpegDecoder: libjpeg-turbo at
// the smallest n/8 scale still at least the capture size). `raypoint run --realtime-format
// mjpeg` replays it, so that the daemon's measured cost includes the decoding a user with an
// MJPEG-only camera pays.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "raypoint/capture/jpeg_decoder.hpp"
#include "raypoint/core/frame.hpp"

namespace raypoint::daemon {

class MjpegClip {
  public:
    // An empty clip of `size` frames at `fps`, decoded to at least `least` (the camera path's
    // capture size: the larger of the working size and [camera] min_width x min_height).
    // Throws std::invalid_argument for a size or rate <= 0, std::runtime_error when libjpeg
    // cannot be set up.
    MjpegClip(cv::Size size, double fps, cv::Size least);

    // Appends one JPEG of size() (not checked here: a frame that does not decode is skipped
    // when it is due, as a camera's corrupt frame is).
    void append(const std::uint8_t* data, std::size_t bytes);

    cv::Size size() const noexcept { return size_; }
    double fps() const noexcept { return fps_; }
    int frame_count() const noexcept { return static_cast<int>(ends_.size()); }
    std::size_t memory_bytes() const noexcept { return bytes_.size(); }
    // The decoder's scale in eighths for this clip's frames (8: full size).
    int scale_eighths() const noexcept { return JpegDecoder::scale_for(size_, least_); }

    // Decodes frame `index` (0 <= index < frame_count()); the view is valid until the next
    // call. Its data is null when the frame does not decode. No allocation once the first frame
    // has been decoded.
    core::FrameView view(int index, core::Timestamp timestamp) noexcept;

  private:
    cv::Size size_;
    double fps_;
    cv::Size least_;
    std::vector<std::uint8_t> bytes_;       // the JPEGs one after another
    std::vector<std::size_t> ends_;         // frame i is bytes_[ends_[i - 1] or 0, ends_[i])
    std::unique_ptr<JpegDecoder> decoder_;  // held by pointer: the clip moves, libjpeg's state not
};

}  // namespace raypoint::daemon
