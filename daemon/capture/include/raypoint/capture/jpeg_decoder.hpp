// SPDX-License-Identifier: MIT
#pragma once
// MJPEG camera frames decoded with libjpeg-turbo, scaled down inside the decoder: a JPEG is
// coded as 8x8 DCT blocks, and libjpeg can reconstruct each block at 1..8 of 8 pixels a side
// (scale_num / scale_denom), skipping most of the inverse DCT, upsampling and colour work. The
// core only needs its working size (160x120 by default), so a 640x480 MJPEG frame is decoded at
// 1/4 straight to 160x120 instead of at full size and then filtered down.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core/mat.hpp>

namespace raypoint::daemon {

struct JpegState;  // libjpeg's structs (jpeg_decoder.cpp): kept out of this header

class JpegDecoder {
  public:
    // Frames are decoded at the smallest scale of n/8 (n = 1..8) whose size is still at least
    // `least` on both axes (full size when the frame is not larger than that). Throws
    // std::runtime_error when libjpeg cannot be set up (out of memory).
    explicit JpegDecoder(cv::Size least);
    ~JpegDecoder();
    JpegDecoder(const JpegDecoder&) = delete;
    JpegDecoder& operator=(const JpegDecoder&) = delete;

    // Decodes one JPEG into bgr() (CV_8UC3, reused from frame to frame: no allocation once the
    // frame size is known). False, with error() saying why, when the data is not a decodable
    // JPEG (a camera's corrupt frame); never throws.
    bool decode(const std::uint8_t* data, std::size_t size) noexcept;

    const cv::Mat& bgr() const noexcept { return bgr_; }
    // The scale of the last decoded frame, in eighths (8: full size).
    int scale_eighths() const noexcept { return scale_eighths_; }
    const char* error() const noexcept;

    // The smallest n/8 scale keeping `frame` at least `least`: n in 1..8. Exposed for tests.
    static int scale_for(cv::Size frame, cv::Size least) noexcept;

  private:
    std::unique_ptr<JpegState> state_;
    cv::Size least_;
    cv::Mat bgr_;
    int scale_eighths_ = 8;
};

}  // namespace raypoint::daemon
