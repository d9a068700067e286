// SPDX-License-Identifier: MIT
#pragma once
// Synthetic input for the core's benchmarks: a dark disk circling over a mildly textured light
// background at 30 fps, drawn (and converted to YUYV) before any timing.

#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"

namespace raypoint::bench {

// The input sizes of the suite, as benchmark arguments: {width, height}.
inline const std::vector<std::vector<long>> input_sizes{
    {320, 240}, {640, 480}, {1280, 720}, {1920, 1080}};

// A clip of `count` frames; BGR frames are CV_8UC3, YUYV ones CV_8U rows of width * 2 bytes.
// The disk goes round and back, so looping over the clip never jumps.
class Clip {
  public:
    Clip(cv::Size size, core::PixelFormat format, int count);

    // Frame `index` of an endless loop, stamped at 30 fps.
    core::FrameView view(long index) const noexcept;
    cv::Size size() const noexcept { return size_; }
    // Where the disk's centre is in frame `index`, in working pixels of a 160x120 image.
    cv::Point2f working_centre(long index) const noexcept;

  private:
    std::size_t frame_of(long index) const noexcept;

    cv::Size size_;
    core::PixelFormat format_;
    std::vector<cv::Mat> frames_;
};

// 0 = BGR, 1 = YUYV, as benchmark arguments.
core::PixelFormat format_argument(long value) noexcept;
const char* format_name(core::PixelFormat format) noexcept;

}  // namespace raypoint::bench
