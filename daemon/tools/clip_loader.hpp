// SPDX-License-Identifier: MIT
#pragma once
// `raypoint run --input CLIP --realtime`: the clip decoded once, before the run, into the YUYV
// frames a webcam of the clip's size would deliver, so that no video decoder runs during it.

#include <string>

#include <opencv2/core/types.hpp>

#include "raypoint/loop/mjpeg_clip.hpp"
#include "raypoint/loop/yuyv_clip.hpp"

namespace raypoint::daemon {

// Every frame of `path` (a video file or an image sequence, as for --input), converted to YUYV,
// at the container's frame rate. Stops early, with a warning, at `max_bytes` of frames. Throws
// InputError (video_source.hpp) when the file cannot be read or holds no frame.
YuyvClip load_yuyv_clip(const std::string& path, std::size_t max_bytes = std::size_t{1} << 30);

// Every frame of `path` compressed as an MJPEG webcam sends it (jpeg_encoder.hpp, at
// mjpeg_quality), to be decoded to at least `least` when due. Stops early, with a warning, at
// `max_bytes` of JPEGs. Throws as load_yuyv_clip().
MjpegClip load_mjpeg_clip(const std::string& path, cv::Size least,
                          std::size_t max_bytes = std::size_t{1} << 30);

// Cheap webcams' MJPEG: their frames measure as quality 80-90 (the quantization tables' scale);
// 85 sits in the middle.
constexpr int mjpeg_quality = 85;

}  // namespace raypoint::daemon
