// SPDX-License-Identifier: MIT
#include "clip_loader.hpp"

#include <malloc.h>

#include "input_error.hpp"
#include "jpeg_encoder.hpp"
#include "raypoint/service/log.hpp"
#include "video_source.hpp"

namespace raypoint::daemon {

YuyvClip load_yuyv_clip(const std::string& path, std::size_t max_bytes) {
    YuyvClip clip = [&] {
        VideoSource video(path, 0.0);
        YuyvClip frames(video.size(), video.fps());
        if (video.frame_count() > 0) {
            const std::size_t fit = max_bytes / frames.frame_bytes();
            frames.reserve(static_cast<int>(std::min<std::size_t>(video.frame_count(), fit)));
        }
        while (auto frame = video.next()) {
            if (frames.memory_bytes() + frames.frame_bytes() > max_bytes) {
                log::warning(path + ": replaying only the first " +
                             std::to_string(frames.frame_count()) + " frames (" +
                             std::to_string(max_bytes >> 20) + " MiB of YUYV)");
                break;
            }
            frames.append(frame->bgr);
        }
        return frames;
    }();  // the decoder and its buffers are gone here
    // Give the decoder's freed heap back to the system, so that the resident set during the run
    // is the daemon's and the clip's, not the decoder's leftovers.
    malloc_trim(0);
    if (clip.frame_count() == 0) throw InputError(path + ": no frame could be decoded");
    return clip;
}

MjpegClip load_mjpeg_clip(const std::string& path, cv::Size least, std::size_t max_bytes) {
    MjpegClip clip = [&] {
        VideoSource video(path, 0.0);
        MjpegClip frames(video.size(), video.fps(), least);
        std::vector<std::uint8_t> jpeg;
        while (auto frame = video.next()) {
            encode_jpeg(frame->bgr, mjpeg_quality, jpeg);
            if (frames.memory_bytes() + jpeg.size() > max_bytes) {
                log::warning(path + ": replaying only the first " +
                             std::to_string(frames.frame_count()) + " frames (" +
                             std::to_string(max_bytes >> 20) + " MiB of MJPEG)");
                break;
            }
            frames.append(jpeg.data(), jpeg.size());
        }
        return frames;
    }();
    malloc_trim(0);  // as load_yuyv_clip(): the decoder's heap back to the system
    if (clip.frame_count() == 0) throw InputError(path + ": no frame could be decoded");
    return clip;
}

}  // namespace raypoint::daemon
