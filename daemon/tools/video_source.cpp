// SPDX-License-Identifier: MIT
#include "video_source.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <opencv2/core/utils/logger.hpp>

#include "input_error.hpp"

namespace raypoint::daemon {

namespace fs = std::filesystem;

VideoSource::VideoSource(const std::string& path, double fps) : path_(path) {
    // FFmpeg and OpenCV write their own diagnostics to stderr; ours are the one line that
    // matters.
    setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    const bool sequence = path.find('%') != std::string::npos;
    if (!sequence) {
        std::error_code error;
        const auto status = fs::status(path, error);
        if (error || !fs::exists(status)) {
            throw InputError(path + ": cannot open: " + std::strerror(ENOENT));
        }
        if (fs::is_directory(status)) throw InputError(path + ": is a directory, not a video");
        if (fs::file_size(path, error) == 0) throw InputError(path + ": empty file, not a video");
    }
    const int api = sequence ? cv::CAP_IMAGES : cv::CAP_FFMPEG;
    if (!capture_.open(path, api) || !capture_.isOpened()) {
        throw InputError(path + (sequence
                                     ? ": no image of the sequence could be read"
                                     : ": cannot decode as video (not a video, or truncated)"));
    }
    const double container_fps = capture_.get(cv::CAP_PROP_FPS);
    fixed_rate_ = fps > 0.0 || sequence;
    // An image sequence has no frame rate of its own (OpenCV reports 1): 30 unless --fps.
    const bool usable = !sequence && container_fps > 0.0 && container_fps < 1000.0;
    fps_ = fps > 0.0 ? fps : (usable ? container_fps : 30.0);
    frame_count_ = std::max(0, static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_COUNT)));
    size_ = {static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_WIDTH)),
             static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_HEIGHT))};
}

std::optional<DecodedFrame> VideoSource::next() {
    DecodedFrame frame;
    if (!capture_.read(frame.bgr) || frame.bgr.empty()) {
        if (index_ == 0) throw InputError(path_ + ": no frame could be decoded");
        // Containers round their frame count; a few missing frames at the end are normal.
        if (frame_count_ > 0 && index_ < frame_count_ - 2 && !fixed_rate_) {
            throw InputError(path_ + ": truncated: decoded " + std::to_string(index_) + " of " +
                             std::to_string(frame_count_) + " frames");
        }
        return std::nullopt;
    }
    if (frame.bgr.type() != CV_8UC3) {
        throw InputError(path_ + ": unsupported pixel type (expected 8-bit colour)");
    }
    // The container's presentation time; frame / fps when it has none or goes backwards.
    core::Timestamp timestamp = core::seconds_to_us(index_ / fps_);
    if (!fixed_rate_) {
        const double msec = capture_.get(cv::CAP_PROP_POS_MSEC);
        const auto container = static_cast<core::Timestamp>(msec * 1000.0);
        if (msec >= 0.0 && container > last_) timestamp = container;
    }
    if (timestamp <= last_) timestamp = last_ + 1;
    last_ = timestamp;
    frame.timestamp = timestamp;
    ++index_;
    return frame;
}

}  // namespace raypoint::daemon
