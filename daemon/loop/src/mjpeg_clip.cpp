// SPDX-License-Identifier: MIT
#include "raypoint/loop/mjpeg_clip.hpp"

#include <stdexcept>

namespace raypoint::daemon {

MjpegClip::MjpegClip(cv::Size size, double fps, cv::Size least)
    : size_(size), fps_(fps), least_(least), decoder_(std::make_unique<JpegDecoder>(least)) {
    if (size_.width <= 0 || size_.height <= 0 || !(fps > 0.0)) {
        throw std::invalid_argument("MjpegClip: needs a size of at least 1x1 and fps > 0");
    }
}

void MjpegClip::append(const std::uint8_t* data, std::size_t bytes) {
    bytes_.insert(bytes_.end(), data, data + bytes);
    ends_.push_back(bytes_.size());
}

core::FrameView MjpegClip::view(int index, core::Timestamp timestamp) noexcept {
    const auto at = static_cast<std::size_t>(index);
    const std::size_t begin = at == 0 ? 0 : ends_[at - 1];
    if (!decoder_->decode(bytes_.data() + begin, ends_[at] - begin)) {
        return core::FrameView{nullptr, 0, 0, 0, core::PixelFormat::bgr, timestamp};
    }
    const cv::Mat& bgr = decoder_->bgr();
    return core::FrameView{
        bgr.data, bgr.cols, bgr.rows, static_cast<int>(bgr.step[0]), core::PixelFormat::bgr,
        timestamp};
}

}  // namespace raypoint::daemon
