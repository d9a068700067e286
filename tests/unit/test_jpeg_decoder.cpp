// SPDX-License-Identifier: MIT
// MJPEG decoding scaled in the DCT (jpeg_decoder.hpp) against OpenCV's full decode resized to
// the same size: the same picture within JPEG's own error, at a fraction of the work.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/capture/jpeg_decoder.hpp"

namespace raypoint::daemon {
namespace {

const cv::Size working{160, 120};

// A webcam-like picture: a lit gradient, a dark disk (the target) and some texture.
cv::Mat scene(cv::Size size) {
    cv::Mat bgr(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            bgr.at<cv::Vec3b>(y, x) =
                cv::Vec3b(static_cast<std::uint8_t>(150 + 80 * x / size.width),
                          static_cast<std::uint8_t>(170 + 60 * y / size.height),
                          static_cast<std::uint8_t>(190));
        }
    }
    const double s = size.width / 640.0;
    cv::circle(bgr, {static_cast<int>(300 * s), static_cast<int>(220 * s)},
               static_cast<int>(70 * s), cv::Scalar(40, 50, 60), cv::FILLED, cv::LINE_AA);
    cv::rectangle(bgr, {static_cast<int>(40 * s), static_cast<int>(40 * s)},
                  {static_cast<int>(120 * s), static_cast<int>(400 * s)}, cv::Scalar(90, 30, 160),
                  cv::FILLED);
    return bgr;
}

std::vector<std::uint8_t> encode(const cv::Mat& bgr, int quality = 85) {
    std::vector<std::uint8_t> jpeg;
    EXPECT_TRUE(cv::imencode(".jpg", bgr, jpeg, {cv::IMWRITE_JPEG_QUALITY, quality}));
    return jpeg;
}

// Mean and largest absolute difference over all channels.
std::pair<double, double> difference(const cv::Mat& a, const cv::Mat& b) {
    cv::Mat d;
    cv::absdiff(a, b, d);
    double largest = 0.0;
    cv::minMaxLoc(d.reshape(1), nullptr, &largest);
    const cv::Scalar mean = cv::mean(d);
    return {(mean[0] + mean[1] + mean[2]) / 3.0, largest};
}

TEST(JpegDecoder, ScaleIsTheSmallestEighthsKeepingTheWorkingSize) {
    EXPECT_EQ(JpegDecoder::scale_for({640, 480}, working), 2);    // 160x120 exactly
    EXPECT_EQ(JpegDecoder::scale_for({1280, 720}, working), 2);   // 1/8 is 160x90: too low
    EXPECT_EQ(JpegDecoder::scale_for({1920, 1080}, working), 1);  // 240x135
    EXPECT_EQ(JpegDecoder::scale_for({320, 240}, working), 4);
    EXPECT_EQ(JpegDecoder::scale_for({352, 288}, working), 4);  // 176x144: 3/8 is 132x108
    EXPECT_EQ(JpegDecoder::scale_for({160, 120}, working), 8);
    EXPECT_EQ(JpegDecoder::scale_for({100, 80}, working), 8);  // smaller: never upscaled
}

TEST(JpegDecoder, QuarterScaleMatchesAFullDecodeResized) {
    const cv::Mat original = scene({640, 480});
    const std::vector<std::uint8_t> jpeg = encode(original);
    JpegDecoder decoder(working);
    ASSERT_TRUE(decoder.decode(jpeg.data(), jpeg.size())) << decoder.error();
    EXPECT_EQ(decoder.scale_eighths(), 2);
    ASSERT_EQ(decoder.bgr().size(), cv::Size(160, 120));
    ASSERT_EQ(decoder.bgr().type(), CV_8UC3);

    cv::Mat full = cv::imdecode(jpeg, cv::IMREAD_COLOR);
    cv::Mat resized;
    cv::resize(full, resized, {160, 120}, 0, 0, cv::INTER_AREA);
    const auto [mean, largest] = difference(decoder.bgr(), resized);
    // The DCT's reduced inverse is a box filter of 4x4 pixels, as INTER_AREA is; they differ
    // by JPEG's own ringing and rounding, most at the disk's and the bar's edges.
    EXPECT_LT(mean, 1.5);
    EXPECT_LT(largest, 40.0);
    // And the colours are the right way round (BGR): the bar is red-violet, red above blue.
    const cv::Vec3b bar = decoder.bgr().at<cv::Vec3b>(50, 20);
    EXPECT_GT(bar[2], bar[0] + 40);
}

TEST(JpegDecoder, FullScaleMatchesOpenCvsDecode) {
    // The camera's default (CameraOptions::scaled_mjpeg off): the mode's own size as the least.
    const std::vector<std::uint8_t> jpeg = encode(scene({640, 480}));
    JpegDecoder decoder({640, 480});
    ASSERT_TRUE(decoder.decode(jpeg.data(), jpeg.size())) << decoder.error();
    EXPECT_EQ(decoder.scale_eighths(), 8);
    const auto [mean, largest] = difference(decoder.bgr(), cv::imdecode(jpeg, cv::IMREAD_COLOR));
    EXPECT_LT(mean, 0.5);  // the same libjpeg at the same scale: up to colour rounding
    EXPECT_LE(largest, 4.0);
}

TEST(JpegDecoder, CorruptAndTruncatedFramesAreRefusedAndTheNextDecodes) {
    JpegDecoder decoder(working);
    const std::vector<std::uint8_t> noise(2000, 0x5a);
    EXPECT_FALSE(decoder.decode(noise.data(), noise.size()));
    EXPECT_STRNE(decoder.error(), "");
    const std::vector<std::uint8_t> jpeg = encode(scene({640, 480}));
    EXPECT_FALSE(decoder.decode(jpeg.data(), jpeg.size() / 2));
    EXPECT_STRNE(decoder.error(), "");
    ASSERT_TRUE(decoder.decode(jpeg.data(), jpeg.size())) << decoder.error();
    EXPECT_EQ(decoder.bgr().size(), cv::Size(160, 120));
}

}  // namespace
}  // namespace raypoint::daemon
