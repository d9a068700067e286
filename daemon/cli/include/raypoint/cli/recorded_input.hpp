// SPDX-License-Identifier: MIT
#pragma once
// `raypoint run --input CLIP`: a recorded video as the daemon's camera. Reading video files needs
// OpenCV's videoio, whose ffmpeg, GStreamer and GDAL dependencies are ~250 shared libraries and
// ~55 MB of resident pages: too much for a service that runs all day. So the command line only
// knows this seam: raypoint-tools passes a factory (daemon/tools/recorded_source.hpp), and the
// service binary `raypoint` passes none and hands `run --input` to raypoint-tools
// (daemon/raypoint/video_tools.hpp).

#include <memory>
#include <string>

#include <opencv2/core/types.hpp>

#include "raypoint/capture/frame_source.hpp"

namespace raypoint::daemon {

struct RecordedInput {
    std::string path;
    bool paced = true;      // at the clip's own frame rate, or as fast as the core runs
    bool realtime = false;  // decoded up front, replayed from memory as a YUYV camera
    bool loop = false;      // with realtime: start again at the end (--duration)
    // With realtime: replayed as an MJPEG camera's frames (compressed up front, decoded when
    // due, at least at `least`, as the camera path decodes them) instead of YUYV.
    bool mjpeg = false;
    cv::Size least;
};

// Opens the clip; throws a std::runtime_error naming the path when it cannot be read as video.
using RecordedSourceFactory = std::unique_ptr<FrameSource> (*)(const RecordedInput& input);

}  // namespace raypoint::daemon
