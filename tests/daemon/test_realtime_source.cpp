// SPDX-License-Identifier: MIT
// --realtime's parts without the daemon: the YUYV conversion of a clip (checked against
// OpenCV's own YUYV decoder) and the replay's order, timestamps, looping, end and drops.

#include <poll.h>

#include <chrono>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/loop/realtime_source.hpp"
#include "raypoint/loop/yuyv_clip.hpp"

namespace raypoint::daemon {
namespace {

// A smooth colour image: chroma subsampling loses nothing where neighbours are alike.
cv::Mat gradient(cv::Size size) {
    cv::Mat bgr(size, CV_8UC3);
    for (int y = 0; y < size.height; ++y) {
        for (int x = 0; x < size.width; ++x) {
            bgr.at<cv::Vec3b>(y, x) =
                cv::Vec3b(static_cast<std::uint8_t>(40 + x % 160),
                          static_cast<std::uint8_t>(30 + y * 190 / size.height),
                          static_cast<std::uint8_t>(200 - x / 4));
        }
    }
    return bgr;
}

// Frames of one grey level each, 10, 20, 30...: which frame came is readable from a pixel.
YuyvClip numbered_clip(int count, double fps) {
    YuyvClip clip({16, 8}, fps);
    for (int i = 0; i < count; ++i)
        clip.append(cv::Mat(8, 16, CV_8UC3, cv::Scalar::all(10.0 * (i + 1))));
    return clip;
}

// The grey level a YUYV frame's first pixel shows: Y back to full range.
int grey_of(const core::FrameView& frame) {
    return static_cast<int>(std::lround((frame.data[0] - 16) * 255.0 / 219.0));
}

TEST(YuyvClip, DecodesBackWithOpenCvsYuyvConversion) {
    const cv::Mat bgr = gradient({64, 48});
    YuyvClip clip(bgr.size(), 30.0);
    clip.append(bgr);
    ASSERT_EQ(clip.frame_count(), 1);
    EXPECT_EQ(clip.memory_bytes(), 64U * 48U * 2U);
    const core::FrameView view = clip.view(0, 123);
    EXPECT_EQ(view.format, core::PixelFormat::yuyv);
    EXPECT_EQ(view.stride, 128);
    EXPECT_EQ(view.timestamp, 123);
    const cv::Mat yuyv(view.height, view.width, CV_8UC2, const_cast<std::uint8_t*>(view.data),
                       static_cast<std::size_t>(view.stride));
    cv::Mat back;
    cv::cvtColor(yuyv, back, cv::COLOR_YUV2BGR_YUYV);
    cv::Mat difference;
    cv::absdiff(back, bgr, difference);
    double worst = 0.0;
    cv::minMaxLoc(difference.reshape(1), nullptr, &worst);
    // Rounding in both directions and the pair's shared chroma on a gentle slope.
    EXPECT_LE(worst, 4.0);
}

TEST(YuyvClip, OddWidthDropsTheLastColumn) {
    YuyvClip clip({65, 10}, 30.0);
    EXPECT_EQ(clip.size(), cv::Size(64, 10));
    clip.append(gradient({65, 10}));
    EXPECT_EQ(clip.view(0, 0).width, 64);
    EXPECT_THROW(clip.append(gradient({40, 10})), std::invalid_argument);
}

TEST(RealtimeSource, FramesInOrderAtTheClipsRateThenTheEnd) {
    // 20 fps: a loaded CI machine would have to stall the test 150 ms before a frame is dropped.
    RealtimeSource source(numbered_clip(4, 20.0), "numbered", false);
    std::vector<core::Timestamp> times;
    for (int i = 0; i < 4; ++i) {
        const Capture capture = source.next(1000);
        ASSERT_EQ(capture.status, CaptureStatus::frame) << i;
        EXPECT_EQ(grey_of(capture.frame), 10 * (i + 1));
        EXPECT_EQ(capture.ready, capture.frame.timestamp);  // due time = capture time
        EXPECT_EQ(capture.frame.format, core::PixelFormat::yuyv);
        times.push_back(capture.frame.timestamp);
    }
    for (std::size_t i = 1; i < times.size(); ++i)
        EXPECT_NEAR(static_cast<double>(times[i] - times[i - 1]), 50000.0, 1.0);  // 20 fps
    const Capture end = source.next(1000);
    EXPECT_EQ(end.status, CaptureStatus::ended);
    EXPECT_EQ(source.delivered(), 4);
    EXPECT_EQ(source.dropped(), 0);
}

TEST(RealtimeSource, LoopsForEver) {
    RealtimeSource source(numbered_clip(3, 50.0), "numbered", true);  // slow enough not to drop
    for (int i = 0; i < 7; ++i) {
        const Capture capture = source.next(1000);
        ASSERT_EQ(capture.status, CaptureStatus::frame) << i;
        EXPECT_EQ(grey_of(capture.frame), 10 * (i % 3 + 1)) << i;
    }
}

TEST(RealtimeSource, TheDescriptorWaitsForTheNextFrame) {
    RealtimeSource source(numbered_clip(2, 1.0), "numbered", false);
    pollfd first{source.wait_fd(), POLLIN, 0};
    ASSERT_EQ(poll(&first, 1, 1000), 1);  // frame 0 is due at once
    ASSERT_EQ(source.next(0).status, CaptureStatus::frame);
    // Frame 1 is due a second later: nothing to read now, and next(0) does not wait for it.
    pollfd second{source.wait_fd(), POLLIN, 0};
    EXPECT_EQ(poll(&second, 1, 0), 0);
    EXPECT_EQ(source.next(0).status, CaptureStatus::timeout);
}

TEST(RealtimeSource, ALateLoopFindsAtMostThreeFramesWaiting) {
    RealtimeSource source(numbered_clip(5, 100.0), "numbered", true);
    const Capture first = source.next(1000);
    ASSERT_EQ(first.status, CaptureStatus::frame);
    // 200 ms asleep at 100 fps: 20 frames came due; a camera's queue keeps the last three.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const Capture late = source.next(0);
    ASSERT_EQ(late.status, CaptureStatus::frame);
    EXPECT_GE(source.dropped(), 17);
    EXPECT_EQ(late.frame.timestamp - first.frame.timestamp, (source.dropped() + 1) * 10'000);
    // The other two waiting come at once, without a wait.
    EXPECT_EQ(source.next(0).status, CaptureStatus::frame);
    EXPECT_EQ(source.next(0).status, CaptureStatus::frame);
}

TEST(RealtimeSource, AnEmptyClipIsRefused) {
    EXPECT_THROW(RealtimeSource(YuyvClip({16, 8}, 30.0), "empty", false), std::invalid_argument);
}

}  // namespace
}  // namespace raypoint::daemon
