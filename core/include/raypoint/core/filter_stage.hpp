// SPDX-License-Identifier: MIT
#pragma once
// The first stage of frame preprocessing (paper 4.1): the Poisson-disk filter and subsampling
// of a camera frame to the working colour, grey and channel images, the current and the
// previous frame's.

#include <array>
#include <cstdint>

#include <opencv2/core.hpp>

#include "raypoint/core/filter_plan.hpp"
#include "raypoint/core/frame.hpp"
#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/poisson_disk.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::core {
namespace detail {
struct FilterOutput;
}

class FilterStage {
  public:
    explicit FilterStage(const PreprocessSettings& settings,
                         InstructionSet instructions = best_instruction_set());

    // Filters and subsamples `frame` into the current images; the ones it replaces become the
    // previous. Returns false for a frame the core cannot read (null data, odd YUYV width,
    // stride too small, smaller than the working size): the frame is skipped, nothing changes.
    // A new input size or format rebuilds the plan (the only allocation) and forgets the
    // previous frame.
    bool apply(const FrameView& frame) noexcept;

    // Takes effect from the next apply(); every set gives the same images, so it may change
    // between any two frames.
    void set_instructions(InstructionSet instructions) noexcept { instructions_ = instructions; }
    InstructionSet instructions() const noexcept { return instructions_; }

    const cv::Mat& color() const noexcept { return color_[current_]; }  // CV_8UC3
    const cv::Mat& previous_color() const noexcept { return color_[1 - current_]; }
    const cv::Mat& gray() const noexcept { return gray_[current_]; }  // CV_8U
    const cv::Mat& previous_gray() const noexcept { return gray_[1 - current_]; }
    // CV_8U, three working heights: the current colour image's B, G and R planes, one above
    // the other (the Sobel loops read them contiguously).
    const cv::Mat& planes() const noexcept { return planes_; }
    // Two frames of the same geometry in a row: the previous images are comparable.
    bool has_previous() const noexcept { return filtered_ >= 2; }
    const FilterPlan& plan() const noexcept { return plan_; }

  private:
    void filter_bgr(const FrameView& frame) noexcept;
    void filter_yuyv(const FrameView& frame) noexcept;
    void start_row(const FrameView& frame, int y) noexcept;
    detail::FilterOutput output_row(int y) noexcept;
    int filter_interior(int begin, const detail::FilterOutput& target) const noexcept;
    void filter_border(const detail::FilterOutput& target) const noexcept;
    void filter_clamped(const detail::FilterOutput& target, int x) const noexcept;
    void prefetch_rows(const FrameView& frame, int next_y) noexcept;
    void set_fetch(const FrameView& frame, int next_y) noexcept;
    static void prefetch(const std::uint8_t* begin, const std::uint8_t* end) noexcept;

    InstructionSet instructions_;
    FilterPlan plan_;
    // Per tap, the input row it reads for the working row being filtered, and the same plus
    // the tap's column shift in bytes (the interior kernels').
    std::array<const std::uint8_t*, poisson_disk_tap_count> tap_row_pointers_{};
    std::array<const std::uint8_t*, poisson_disk_tap_count> shifted_tap_pointers_{};
    std::array<cv::Mat, 2> color_;
    std::array<cv::Mat, 2> gray_;
    cv::Mat planes_;
    // The input lines left to prefetch for a later working row, and how many a kernel step.
    const std::uint8_t* fetch_ = nullptr;
    const std::uint8_t* fetch_end_ = nullptr;
    int fetch_lines_ = 8;
    int current_ = 0;
    long filtered_ = 0;  // frames filtered since the input geometry last changed
};

}  // namespace raypoint::core
