// SPDX-License-Identifier: MIT
#pragma once
// Where the Poisson-disk filter (paper 4.1) reads: for one input size and pixel format, each
// tap's input column and row at every working pixel, and the byte offsets the vector kernels
// use. Built once when the input geometry changes, read on every frame.

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/poisson_disk.hpp"

namespace raypoint::core {

// One tap of the filter, for the plan's input geometry.
struct FilterTap {
    int dx = 0;  // column offset from a working pixel's centre, input pixels
    // Byte shift of the tap's column from its centre's bytes (centre_bytes()): BGR dx * 3;
    // YUYV with interior centres of parity p, ((p + dx) & ~1) * 2, the start of the tap's
    // Y0 U Y1 V group.
    int shift_bytes = 0;
    // YUYV: the tap's Y is the second of its pair (for interior centres of uniform parity).
    bool odd_luma = false;
    std::vector<int> columns;  // per working column, the tap's input column, clamped
    std::vector<int> rows;     // per working row, the tap's input row, clamped
};

// Up to four working columns outside the interior (their taps clamped), filtered together by a
// vector kernel: per tap, where each column's 4-byte load starts in the tap's input row (the
// row's own bytes only), and the byte shuffle (pshufb) that widens its three values to the
// 16-bit lanes [B G R 0] (YUYV: [Y U V 0]), columns 0-1 in the low 16 bytes, 2-3 in the high.
struct FilterBorderGroup {
    std::array<int, 4> columns{};  // working columns; after the first `count`, repeats
    int count = 0;
    struct Tap {
        std::array<int, 4> loads{};
        std::array<std::uint8_t, 32> select{};
    };
    std::array<Tap, poisson_disk_tap_count> taps{};
};

class FilterPlan {
  public:
    // `filter_radius` in pixels of a 640-wide frame (PreprocessSettings::filter_radius); it
    // scales with the input width. No geometry yet: matches() is false until build().
    FilterPlan(cv::Size working, double filter_radius);

    // Plans the filter for this input. Allocates (may throw); on a throw the plan matches no
    // frame, so the next one rebuilds it.
    void build(int input_width, int input_height, PixelFormat format);
    bool matches(const FrameView& frame) const noexcept {
        return frame.width == input_width_ && frame.height == input_height_ &&
               frame.format == format_;
    }

    cv::Size working() const noexcept { return working_; }
    int input_width() const noexcept { return input_width_; }
    int input_height() const noexcept { return input_height_; }
    PixelFormat format() const noexcept { return format_; }

    const std::array<FilterTap, poisson_disk_tap_count>& taps() const noexcept { return taps_; }
    // Per working column, the input column of its centre, and the byte offset of its centre
    // pixel (BGR) or its pair (YUYV) within an input row.
    const std::vector<int>& centre_columns() const noexcept { return centre_columns_; }
    const std::vector<int>& centre_bytes() const noexcept { return centre_bytes_; }
    // Working columns in [interior_begin(), interior_end()) read no clamped tap, with a column
    // to spare on each side (YUYV reads a column's pair); empty when the frame is too narrow.
    int interior_begin() const noexcept { return interior_begin_; }
    int interior_end() const noexcept { return interior_end_; }
    // YUYV: every interior centre has the same parity, so each tap's Y is at a fixed place in
    // its pair and the vector kernels apply.
    bool uniform_parity() const noexcept { return uniform_parity_; }
    // Bit t set where taps()[t].odd_luma: the kernels' per-tap test, one word for all taps.
    std::uint32_t odd_taps() const noexcept { return odd_taps_; }
    // Bytes between neighbouring interior centres (or pairs) when the step is the same across
    // the interior, else 0.
    int centre_step_bytes() const noexcept { return centre_step_bytes_; }
    // A read of n bytes at a tap's shifted row pointer + o stays inside every tap's input row
    // when o + n <= read_limit(): the row's bytes less the largest tap shift.
    int read_limit() const noexcept { return read_limit_; }
    // The working columns the interior kernels leave (all of them for YUYV of mixed parity),
    // four to a group.
    const std::vector<FilterBorderGroup>& border_groups() const noexcept { return border_groups_; }
    // Per working row, the last (largest) input row a tap reads: the filter fetches the rows
    // of the next working row ahead up to it.
    int last_tap_row(int y) const noexcept { return last_tap_rows_[y]; }

  private:
    void plan_border(int input_width, bool bgr);

    cv::Size working_;
    double filter_radius_;
    int input_width_ = 0;
    int input_height_ = 0;
    PixelFormat format_ = PixelFormat::bgr;
    std::array<FilterTap, poisson_disk_tap_count> taps_;
    std::vector<int> centre_columns_;
    std::vector<int> centre_bytes_;
    std::vector<int> last_tap_rows_;
    std::vector<FilterBorderGroup> border_groups_;
    int interior_begin_ = 0;
    int interior_end_ = 0;
    bool uniform_parity_ = false;
    int centre_step_bytes_ = 0;
    int read_limit_ = 0;
    std::uint32_t odd_taps_ = 0;
};

}  // namespace raypoint::core
