// SPDX-License-Identifier: MIT
#pragma once
// FrameEvidence answered from the preprocessed images of a real frame. The edge image is read
// by estimate() alone (TRACKING and RECOVERING, paper 4.2), so it is computed there, on the
// first estimate of a frame: INITIALIZING and SEARCHING frames, and the frame a search picks a
// target on, never pay for the edge stage.

#include "quiet_frame.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/state_machine.hpp"

namespace raypoint::core::detail {

class ImageEvidence final : public FrameEvidence {
  public:
    ImageEvidence(Preprocessor& images, Estimator& estimator, const TrackingSettings& settings,
                  int compensation_minima) noexcept
        : images_(images),
          estimator_(estimator),
          settings_(settings),
          compensation_minima_(compensation_minima) {}

    double movement() const noexcept override { return images_.movement(); }
    double movement_near(cv::Point2f centre, float radius) const noexcept override;
    std::optional<cv::Point2f> detect() noexcept override;
    Estimate estimate(cv::Point2f inner) noexcept override;
    Estimate look(cv::Point2f inner) noexcept override;
    cv::Vec3f current_color(cv::Point2f at) const noexcept override {
        return patch_mean(images_.color(), at);
    }
    cv::Vec3f previous_color(cv::Point2f at) const noexcept override {
        return patch_mean(images_.previous_color(), at);
    }

    void forget_target() noexcept override {
        on_end_ = false;
        estimator_.forget_target();
    }
    void keep_quiet_frame() noexcept override { quiet_.keep(images_.color()); }
    std::optional<cv::Point2f> change(double threshold) noexcept override {
        return quiet_.change(images_.color(), threshold, compensation_minima_);
    }
    std::optional<cv::Vec3f> quiet_color(cv::Point2f at) const noexcept override {
        if (!quiet_.kept() || quiet_.frame().size() != images_.color().size()) return std::nullopt;
        return patch_mean(quiet_.frame(), at);
    }

  private:
    bool end_is_moving(const Estimate& estimate) const noexcept;
    cv::Vec3f patch_mean(const cv::Mat& color, cv::Point2f at) const noexcept;

    Preprocessor& images_;
    Estimator& estimator_;
    const TrackingSettings& settings_;
    int compensation_minima_;  // PreprocessSettings::compensation_minima
    QuietFrame quiet_;
    bool on_end_ = false;  // the target is a border-crossing region's far end
};

}  // namespace raypoint::core::detail
