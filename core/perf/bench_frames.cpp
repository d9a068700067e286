// SPDX-License-Identifier: MIT
#include "bench_frames.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace raypoint::bench {
namespace {

constexpr double angle_step = 0.08;  // radians a frame: about 12 working pixels a second

cv::Point2d centre_fraction(double angle) {
    return {0.5 + 0.2 * std::cos(angle), 0.5 + 0.2 * std::sin(angle)};
}

// BT.601 limited range, the inverse of what the core reads from a V4L2 YUYV buffer.
cv::Mat to_yuyv(const cv::Mat& bgr) {
    cv::Mat yuv;
    cv::cvtColor(bgr, yuv, cv::COLOR_BGR2YUV);
    cv::Mat packed(bgr.rows, bgr.cols * 2, CV_8U);
    for (int y = 0; y < bgr.rows; ++y) {
        const auto* in = yuv.ptr<cv::Vec3b>(y);
        auto* row = packed.ptr<std::uint8_t>(y);
        for (int x = 0; x + 1 < bgr.cols; x += 2) {
            row[2 * x + 0] = in[x][0];
            row[2 * x + 1] = static_cast<std::uint8_t>((in[x][1] + in[x + 1][1]) / 2);
            row[2 * x + 2] = in[x + 1][0];
            row[2 * x + 3] = static_cast<std::uint8_t>((in[x][2] + in[x + 1][2]) / 2);
        }
    }
    return packed;
}

}  // namespace

Clip::Clip(cv::Size size, core::PixelFormat format, int count) : size_(size), format_(format) {
    cv::Mat background(size, CV_8UC3);
    cv::RNG random(7);
    random.fill(background, cv::RNG::UNIFORM, cv::Scalar::all(180), cv::Scalar::all(230));
    cv::GaussianBlur(background, background, {0, 0}, 3.0);
    for (int i = 0; i < count; ++i) {
        cv::Mat frame = background.clone();
        const cv::Point2d at = centre_fraction(i * angle_step);
        cv::circle(
            frame,
            cv::Point(static_cast<int>(size.width * at.x), static_cast<int>(size.height * at.y)),
            size.height / 8, cv::Scalar(40, 30, 30), cv::FILLED, cv::LINE_AA);
        frames_.push_back(format == core::PixelFormat::yuyv ? to_yuyv(frame) : frame);
    }
}

std::size_t Clip::frame_of(long index) const noexcept {
    const auto count = static_cast<long>(frames_.size());
    const long period = count > 1 ? 2 * (count - 1) : 1;
    const long phase = index % period;
    return static_cast<std::size_t>(phase < count ? phase : period - phase);
}

core::FrameView Clip::view(long index) const noexcept {
    const cv::Mat& frame = frames_[frame_of(index)];
    return {frame.data, size_.width,   size_.height, static_cast<int>(frame.step),
            format_,    index * 33'333};
}

cv::Point2f Clip::working_centre(long index) const noexcept {
    const cv::Point2d at = centre_fraction(static_cast<double>(frame_of(index)) * angle_step);
    return {static_cast<float>(at.x * 160.0 - 0.5), static_cast<float>(at.y * 120.0 - 0.5)};
}

core::PixelFormat format_argument(long value) noexcept {
    return value == 0 ? core::PixelFormat::bgr : core::PixelFormat::yuyv;
}

const char* format_name(core::PixelFormat format) noexcept {
    return format == core::PixelFormat::bgr ? "bgr" : "yuyv";
}

}  // namespace raypoint::bench
