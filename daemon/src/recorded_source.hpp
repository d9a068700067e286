#pragma once
// `raypoint run --input CLIP`: a recorded video as the daemon's camera. Reading video files needs
// OpenCV's videoio, whose ffmpeg, GStreamer and GDAL dependencies are ~250 shared libraries and
// ~55 MB of resident pages: too much for a service that runs all day. So only raypoint-tools
// (tools_main.cpp) links it and passes make_recorded_source to run_command; the service binary
// `raypoint` passes nothing and hands `run --input` to raypoint-tools (video_tools.hpp).

#include <memory>
#include <string>

#include "frame_source.hpp"

namespace raypoint::daemon {

struct RecordedInput {
    std::string path;
    bool paced = true;      // at the clip's own frame rate, or as fast as the core runs
    bool realtime = false;  // decoded up front, replayed from memory as a YUYV camera
    bool loop = false;      // with realtime: start again at the end (--duration)
};

// Throws InputError (errors.hpp) when the file cannot be read as video.
using RecordedSourceFactory = std::unique_ptr<FrameSource> (*)(const RecordedInput& input);

std::unique_ptr<FrameSource> make_recorded_source(const RecordedInput& input);

}  // namespace raypoint::daemon
