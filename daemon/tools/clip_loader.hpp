// SPDX-License-Identifier: MIT
#pragma once
// `raypoint run --input CLIP --realtime`: the clip decoded once, before the run, into the YUYV
// frames a webcam of the clip's size would deliver, so that no video decoder runs during it.

#include <string>

#include "raypoint/loop/yuyv_clip.hpp"

namespace raypoint::daemon {

// Every frame of `path` (a video file or an image sequence, as for --input), converted to YUYV,
// at the container's frame rate. Stops early, with a warning, at `max_bytes` of frames. Throws
// InputError (video_source.hpp) when the file cannot be read or holds no frame.
YuyvClip load_yuyv_clip(const std::string& path, std::size_t max_bytes = std::size_t{1} << 30);

}  // namespace raypoint::daemon
