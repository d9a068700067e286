// SPDX-License-Identifier: MIT
#pragma once
// The third stage of frame preprocessing (paper 4.1): the absolute difference of two working
// images, its brightness compensation (the largest of the 10 smallest distinct values is
// subtracted) and the global inter-frame movement value.

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/settings.hpp"

namespace raypoint::core {

// The brightness compensation of paper 4.1: the largest of the `minima` smallest distinct values
// present in `difference` (when fewer values are distinct, the largest present value). At most
// `minima` minimum passes over the pixels, no sorting.
int brightness_offset(const cv::Mat& difference, int minima) noexcept;

class DifferenceStage {
  public:
    explicit DifferenceStage(const PreprocessSettings& settings);

    // The compensated difference of `grey` and `previous_grey` (CV_8U, the working size) and
    // the movement value; `color` and `previous_color` (CV_8UC3, the working size) are read
    // only when the movement comes from the channels (PreprocessSettings::movement_source
    // EdgeSource::max_channel).
    void compute(const cv::Mat& grey, const cv::Mat& previous_grey, const cv::Mat& color,
                 const cv::Mat& previous_color) noexcept;
    // No previous frame: an empty difference, no movement, no offset.
    void reset() noexcept;

    const cv::Mat& difference() const noexcept { return difference_; }  // CV_8U compensated
    // Sum of the compensated difference over the working pixels (paper 4.1 "global inter-frame
    // movement value"; the paper's average times the pixel count, see docs/settings.md), from
    // the grey difference or the per-channel one (PreprocessSettings::movement_source).
    double movement() const noexcept { return movement_; }
    int brightness_offset_applied() const noexcept { return offset_; }
    // Compensation::rows, after a compute() that kept the relit difference: the previous colour
    // image in the current frame's light (CV_8UC3, each row times its band's light ratio), what
    // the current frame would show of a still scene. relit() is false otherwise (always under
    // Compensation::frame, and after reset()).
    bool relit() const noexcept { return relit_current_; }
    // How far the light changed since the previous frame, relative, by as much in every band
    // of rows and the same way (0.3: every band at least 30% brighter, or every band 30%
    // darker), when the relit difference was kept; 0 otherwise. A camera's gain or exposure
    // jump lights the whole picture alike; flicker's bands go brighter and darker by turns.
    double light_change() const noexcept { return light_change_; }
    const cv::Mat& previous_color_relit() const noexcept { return relit_; }

  private:
    bool estimate_row_gains(const cv::Mat& grey, const cv::Mat& previous_grey) noexcept;

    bool channels_;  // the movement value from the largest per-channel difference
    bool rows_;      // Compensation::rows: each band of rows' light ratio divided out first
    int minima_;
    cv::Mat difference_;
    // Each pixel's largest channel difference, a row of the working width after another (the
    // pixels of a row in an order of their own: only the offset and the sum are read).
    std::vector<std::uint8_t> strongest_;
    // Compensation::rows: each band's and each row's light ratio, current / previous, in 1/256,
    // and 2^24 / value, which turns the ratio's division into a multiplication.
    std::vector<int> band_gains_;
    std::vector<int> row_gains_;
    std::array<std::uint32_t, 256> reciprocal_{};
    std::vector<std::uint8_t> grey_row_;  // a row of the previous grey image, relit
    cv::Mat relit_;
    cv::Mat relit_difference_;  // the grey difference with the previous image relit
    bool relit_current_ = false;
    double light_change_ = 0.0;
    double movement_ = 0.0;
    int offset_ = 0;
};

}  // namespace raypoint::core
