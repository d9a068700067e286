// SPDX-License-Identifier: MIT
#pragma once
// A camera frame as the core sees it: borrowed pixels plus the time they were captured.

#include <cstdint>

namespace raypoint::core {

// Microseconds on a monotonic clock. Only differences matter: the core never reads a clock,
// so a recorded clip replays exactly as it ran live (docs/design.md rule 2).
using Timestamp = std::int64_t;

// Every conversion from seconds to Timestamp goes through these, so all round the same way.
constexpr Timestamp seconds_to_us(double seconds) noexcept {
    return static_cast<Timestamp>(seconds * 1e6);
}
// Whole seconds (a timespec's or timeval's tv_sec), exactly.
constexpr Timestamp seconds_to_us(std::int64_t seconds) noexcept {
    return seconds * 1'000'000;
}

enum class PixelFormat {
    bgr,   // 3 bytes a pixel, B G R (OpenCV's order)
    yuyv,  // 4 bytes for 2 pixels, Y0 U Y1 V (V4L2_PIX_FMT_YUYV); width must be even
};

// Pixels are not owned and must stay valid during Tracker::process().
struct FrameView {
    const std::uint8_t* data = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;  // bytes from one row to the next
    PixelFormat format = PixelFormat::bgr;
    Timestamp timestamp = 0;
};

}  // namespace raypoint::core
