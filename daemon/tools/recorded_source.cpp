// SPDX-License-Identifier: MIT
#include "recorded_source.hpp"

#include "clip_loader.hpp"
#include "file_frame_source.hpp"
#include "raypoint/loop/realtime_source.hpp"

namespace raypoint::daemon {

std::unique_ptr<FrameSource> make_recorded_source(const RecordedInput& input) {
    if (input.realtime && input.mjpeg) {
        return std::make_unique<RealtimeSource>(load_mjpeg_clip(input.path, input.least),
                                                input.path, input.loop);
    }
    if (input.realtime) {
        return std::make_unique<RealtimeSource>(load_yuyv_clip(input.path), input.path, input.loop);
    }
    return std::make_unique<FileFrameSource>(input.path, input.paced);
}

}  // namespace raypoint::daemon
