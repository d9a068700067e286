// SPDX-License-Identifier: MIT
#include "raypoint/loop/yuyv_clip.hpp"

#include <stdexcept>

#include <opencv2/core.hpp>

namespace raypoint::daemon {

YuyvClip::YuyvClip(cv::Size size, double fps) : size_(size.width / 2 * 2, size.height), fps_(fps) {
    if (size_.width <= 0 || size_.height <= 0 || !(fps > 0.0)) {
        throw std::invalid_argument("YuyvClip: needs a size of at least 2x1 and fps > 0");
    }
}

void YuyvClip::append(const cv::Mat& bgr) {
    if (bgr.type() != CV_8UC3 || bgr.cols < size_.width || bgr.rows < size_.height) {
        throw std::invalid_argument(
            "YuyvClip::append: needs a BGR frame of at least the clip's size");
    }
    // BT.601 limited range (Y 16..235, U and V 16..240 around 128), what V4L2 webcams mean by
    // YUYV and what the core's YUYV path decodes. Columns: B, G, R, then the offset.
    static const cv::Matx34f bgr_to_yuv(0.0979F, 0.5041F, 0.2568F, 16.0F,     //
                                        0.4392F, -0.2910F, -0.1482F, 128.0F,  //
                                        -0.0714F, -0.3678F, 0.4392F, 128.0F);
    cv::transform(bgr(cv::Rect(0, 0, size_.width, size_.height)), yuv_, bgr_to_yuv);
    const std::size_t start = bytes_.size();
    bytes_.resize(start + frame_bytes());
    for (int y = 0; y < size_.height; ++y) {
        const auto* in = yuv_.ptr<cv::Vec3b>(y);
        std::uint8_t* out = bytes_.data() + start + std::size_t(stride()) * y;
        // Two pixels share one U and one V: their mean, rounded.
        for (int x = 0; x < size_.width; x += 2) {
            out[x * 2] = in[x][0];
            out[x * 2 + 1] = static_cast<std::uint8_t>((in[x][1] + in[x + 1][1] + 1) / 2);
            out[x * 2 + 2] = in[x + 1][0];
            out[x * 2 + 3] = static_cast<std::uint8_t>((in[x][2] + in[x + 1][2] + 1) / 2);
        }
    }
}

core::FrameView YuyvClip::view(int index, core::Timestamp timestamp) const noexcept {
    return core::FrameView{bytes_.data() + frame_bytes() * std::size_t(index),
                           size_.width,
                           size_.height,
                           stride(),
                           core::PixelFormat::yuyv,
                           timestamp};
}

}  // namespace raypoint::daemon
