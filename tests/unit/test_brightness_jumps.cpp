// SPDX-License-Identifier: MIT
// Paper 4.1/4.2: a camera's sudden exposure change must not start a search; a moving object
// must. The real Preprocessor on rendered frames feeds the StateMachine through a minimal
// FrameEvidence (movement, centre of mass of the difference, raster estimates, patch colours).

#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/state_machine.hpp"

namespace raypoint::core {
namespace {

class PreprocessorEvidence final : public FrameEvidence {
  public:
    explicit PreprocessorEvidence(const Preprocessor& images)
        : images_(images), estimator_(make_estimator(EstimatorSettings{})) {}

    double movement() const noexcept override { return images_.movement(); }
    double movement_near(cv::Point2f, float) const noexcept override { return images_.movement(); }
    std::optional<cv::Point2f> detect() noexcept override {
        const cv::Moments m = cv::moments(images_.difference());
        if (m.m00 <= 0.0) return std::nullopt;
        return cv::Point2f(static_cast<float>(m.m10 / m.m00), static_cast<float>(m.m01 / m.m00));
    }
    Estimate estimate(cv::Point2f inner) noexcept override {
        return estimator_->estimate(images_.edges(), inner);
    }
    cv::Vec3f current_color(cv::Point2f at) const noexcept override {
        return mean(images_.color(), at);
    }
    cv::Vec3f previous_color(cv::Point2f at) const noexcept override {
        return mean(images_.previous_color(), at);
    }

  private:
    static cv::Vec3f mean(const cv::Mat& image, cv::Point2f at) {
        const cv::Rect patch = cv::Rect(cvRound(at.x) - 2, cvRound(at.y) - 2, 5, 5) &
                               cv::Rect(0, 0, image.cols, image.rows);
        const cv::Scalar m = cv::mean(image(patch));
        return {static_cast<float>(m[0]), static_cast<float>(m[1]), static_cast<float>(m[2])};
    }

    const Preprocessor& images_;
    std::unique_ptr<Estimator> estimator_;
};

// A static, textured 640x480 room with per-frame sensor noise of +-2 and an exposure offset:
// `exposure` on every channel plus 0..3 more by 16x16 tile (the change is not quite uniform).
// A dark disk of radius 80 stands in it at `disk_x`, under the same exposure.
cv::Mat room(int frame, int exposure, int disk_x = 150) {
    cv::Mat base(480, 640, CV_16SC3);
    for (int y = 0; y < 480; ++y) {
        for (int x = 0; x < 640; ++x) {
            const int v =
                90 + static_cast<int>(40.0 * std::sin(x / 23.0) + 30.0 * std::cos(y / 17.0));
            const int tile = exposure == 0 ? 0 : (x / 16 + y / 16) % 4;
            const auto e = static_cast<short>(exposure + tile);
            base.at<cv::Vec3s>(y, x) =
                cv::Vec3s(static_cast<short>(v + e), static_cast<short>(v * 4 / 5 + 20 + e),
                          static_cast<short>(170 - v / 2 + e));
        }
    }
    cv::circle(base, cv::Point(disk_x, 240), 80, cv::Scalar(10, 15, 20) + cv::Scalar::all(exposure),
               cv::FILLED);
    cv::Mat noise(480, 640, CV_16SC3);
    cv::RNG rng(static_cast<std::uint64_t>(1000 + frame));
    rng.fill(noise, cv::RNG::UNIFORM, -2, 3);
    cv::Mat frame_bgr;
    cv::Mat(base + noise).convertTo(frame_bgr, CV_8UC3);
    return frame_bgr;
}

TEST(BrightnessJumps, DoNotStartASearchButAMovingObjectDoes) {
    Preprocessor pre(PreprocessSettings{});
    PreprocessorEvidence evidence(pre);
    TrackingSettings settings = paper_settings().tracking;  // search above 57,600
    settings.startup_seconds = 0.0;
    StateMachine machine(settings, cv::Size(160, 120));
    const auto at = [](int frame) { return static_cast<Timestamp>(frame) * 33'333; };

    // Frames 0-9 at exposure 0, 10-19 at +30, 20-29 at +5 (a -25 jump); the disk stands
    // still until frame 30, then moves 64 px a frame.
    for (int frame = 0; frame < 30; ++frame) {
        const int exposure = frame < 10 ? 0 : frame < 20 ? 30 : 5;
        const cv::Mat image = room(frame, exposure);
        ASSERT_TRUE(pre.process(test::bgr_view(image, at(frame))));
        const StepResult r = machine.step(at(frame), evidence);
        SCOPED_TRACE(::testing::Message() << "frame " << frame);
        EXPECT_EQ(r.state, TrackerState::searching);
        EXPECT_LT(pre.movement(), 57600.0);
        if (frame == 10 || frame == 20) {
            // Uncompensated, every pixel changed by 25-33: over 19,200 pixels that is more
            // than 480,000. The offset took it.
            EXPECT_GE(pre.brightness_offset_applied(), 24);
        } else if (frame > 0) {
            EXPECT_LE(pre.brightness_offset_applied(), 3);  // noise only
        }
    }
    int acquired_at = -1;
    for (int frame = 30; frame < 40 && acquired_at < 0; ++frame) {
        const int disk_x = 150 + 64 * (frame - 29);
        const cv::Mat image = room(frame, 5, disk_x);
        ASSERT_TRUE(pre.process(test::bgr_view(image, at(frame))));
        const StepResult r = machine.step(at(frame), evidence);
        if (!r.acquired) continue;
        acquired_at = frame;
        EXPECT_GT(pre.movement(), 57600.0);
        // Picked between the disk's old and new places (working pixels: input / 4): the
        // difference's mass is the trailing and leading crescents.
        const cv::Point2f middle(static_cast<float>(disk_x - 32) / 4.0F, 60.0F);
        EXPECT_LT(cv::norm(r.estimate.inner - middle), 80 / 4.0) << r.estimate.inner;
    }
    EXPECT_EQ(acquired_at, 30);
}

}  // namespace
}  // namespace raypoint::core
