// SPDX-License-Identifier: MIT
#pragma once
// Which of the modes a camera offers to capture in: a pure choice, no device involved, so every
// driver's odd list can be unit-tested.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/types.hpp>

namespace raypoint::daemon {

// A frame-size range as VIDIOC_ENUM_FRAMESIZES reports it for V4L2_FRMSIZE_TYPE_STEPWISE (and
// CONTINUOUS, which is stepwise with a step of 1): min + k * step up to max, per axis.
struct SizeRange {
    cv::Size min;
    cv::Size max;
    cv::Size step{1, 1};

    friend bool operator==(const SizeRange&, const SizeRange&) = default;
};

// One entry of what a camera offers: a pixel format (V4L2_PIX_FMT_* fourcc) with either one
// discrete size or a range of sizes.
struct CameraMode {
    std::uint32_t fourcc = 0;
    cv::Size size;                   // the discrete size; unused when `range` is set
    std::optional<SizeRange> range;  // set for stepwise/continuous entries

    friend bool operator==(const CameraMode&, const CameraMode&) = default;
};

// The mode to ask VIDIOC_S_FMT for, always with a concrete size (no range). Preference:
// 1. YUYV at the smallest size >= `working` on both axes (the core reads YUYV's luma directly;
//    the fewest bytes a frame to copy over USB and to filter),
// 2. else MJPEG (or JPEG) at the smallest such size (decoded on the CPU: the slow path),
// 3. else nothing: the core skips frames smaller than its working size, and the other formats
//    have no FrameView format yet (TODO: GREY, for IR cameras, needs core::PixelFormat::grey).
// "Smallest" is by area, then width. Sizes from a range are the smallest grid point >= working;
// YUYV widths are rounded up to even (2 pixels share a U and V).
std::optional<CameraMode> choose_format(const std::vector<CameraMode>& offered, cv::Size working);

// "YUYV", "MJPG", or the four characters of any other fourcc.
std::string fourcc_name(std::uint32_t fourcc);

// "YUYV 640x480" (a discrete mode) or "MJPG 16x16..1920x1080 step 8x8" (a range).
std::string describe(const CameraMode& mode);

}  // namespace raypoint::daemon
