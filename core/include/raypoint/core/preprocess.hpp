#pragma once
// Frame preprocessing (paper 4.1): Poisson-disk filter, subsampling to the working size, Sobel
// edge image, brightness-compensated absolute difference and the global movement value.

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::core {
namespace detail {
struct FilterOutput;
}

// The Poisson-disk filter's tap count: a power of two, so the taps' mean is a shift.
inline constexpr int poisson_disk_tap_count = 16;

// Offsets of the Poisson-disk filter's taps in a unit disk: a fixed, deterministic sample set
// (best-candidate sampling, minimum spacing about 0.45 radius) including the centre.
const std::vector<cv::Point2f>& poisson_disk_taps();

// The brightness compensation of paper 4.1: the largest of the `minima` smallest distinct values
// present in `difference` (0 when there are fewer distinct values than that is impossible: then
// the largest present value). Histogram based, so O(pixels) and no sorting.
int brightness_offset(const cv::Mat& difference, int minima) noexcept;

// The widest vector instructions preprocessing may use. Every set gives the same images bit
// for bit; only the time differs (docs/performance.md).
enum class InstructionSet {
    scalar,
    sse2,  // part of x86-64
    avx2,  // chosen at run time when the CPU has it
};
InstructionSet best_instruction_set() noexcept;
std::string_view to_string(InstructionSet set) noexcept;

class Preprocessor {
  public:
    explicit Preprocessor(const PreprocessSettings& settings,
                          InstructionSet instructions = best_instruction_set());

    // Returns false for a frame the core cannot read (null data, odd YUYV width, stride too
    // small, smaller than the working size): the frame is skipped, nothing changes.
    bool process(const FrameView& frame) noexcept;

    // process() is these three stages in order; they are public for the per-stage benchmarks
    // (core/perf) and do nothing else apart. filter() takes the frame as above (Poisson-disk
    // filter and subsampling to the colour, grey and channel images); the other two recompute
    // their images from the last filtered ones, so repeating them changes nothing.
    bool filter(const FrameView& frame) noexcept;
    void compute_edges() noexcept;
    void compute_difference() noexcept;

    const cv::Mat& color() const noexcept { return color_[current_]; }  // CV_8UC3
    const cv::Mat& previous_color() const noexcept { return color_[1 - current_]; }
    const cv::Mat& gray() const noexcept { return gray_[current_]; }  // CV_8U
    const cv::Mat& magnitude() const noexcept { return magnitude_; }  // CV_8U Sobel magnitude
    // CV_8U: the magnitude where it is over the edge threshold, 0 elsewhere.
    const cv::Mat& edges() const noexcept { return edges_; }
    const cv::Mat& difference() const noexcept { return difference_; }  // CV_8U compensated
    bool has_previous() const noexcept { return processed_ >= 2; }
    // Sum of the compensated difference over the working pixels (paper 4.1 "global inter-frame
    // movement value"; the paper's average times the pixel count, see docs/settings.md), from
    // the grey difference or the per-channel one (PreprocessSettings::movement_source).
    double movement() const noexcept { return movement_; }
    int brightness_offset_applied() const noexcept { return offset_; }

  private:
    void prepare(const FrameView& frame);
    void filter_bgr(const FrameView& frame) noexcept;
    void filter_yuyv(const FrameView& frame) noexcept;
    void start_row(const FrameView& frame, int y) noexcept;
    void shift_taps(int sign) noexcept;
    detail::FilterOutput output_row(int y) noexcept;
    int filter_interior(int begin, const detail::FilterOutput& target) const noexcept;
    void prefetch_rows(const FrameView& frame, int next_y) const noexcept;

    PreprocessSettings settings_;
    InstructionSet instructions_;
    int input_width_ = 0;
    int input_height_ = 0;
    PixelFormat input_format_ = PixelFormat::bgr;
    // Per tap, the clamped input column (in pixels) and row of each working column and row.
    std::vector<std::vector<int>> tap_columns_;
    std::vector<std::vector<int>> tap_rows_;
    // Per tap, the column offset from a working pixel's centre; per working column, the input
    // column of its centre. Working columns in [interior_begin_, interior_end_) need no clamping.
    std::vector<int> tap_dx_;
    std::vector<int> centre_columns_;
    // Per working column, the byte offset of its centre pixel (BGR) or its pair (YUYV); per
    // tap, the byte shift of its column from there (see detail::FilterRow).
    std::vector<int> centre_bytes_;
    std::vector<int> tap_shift_bytes_;
    // YUYV: every interior working column's centre has the same parity, so a tap's Y is at a
    // fixed place in its pair (tap_odd_).
    bool uniform_parity_ = false;
    std::vector<unsigned char> tap_odd_;
    int interior_begin_ = 0;
    int interior_end_ = 0;
    std::vector<const std::uint8_t*> tap_row_pointers_;
    std::vector<int> squared_channels_;  // one row of squared Sobel magnitudes, per channel
    std::vector<int> last_tap_row_;      // per working row, the lowest input row a tap reads
    std::array<cv::Mat, 2> color_;
    std::array<cv::Mat, 2> gray_;
    cv::Mat planes_;  // the current colour image's B, G and R planes, one above the other
    int current_ = 0;
    long processed_ = 0;
    cv::Mat magnitude_;
    cv::Mat edges_;
    cv::Mat difference_;
    std::vector<std::uint8_t> channel_row_;  // a row of channel differences, then their maxima
    // Histograms of the grey and the per-channel difference, four interleaved partial ones each.
    std::array<std::array<int, 256>, 4> grey_bins_{};
    std::array<std::array<int, 256>, 4> channel_bins_{};
    double movement_ = 0.0;
    int offset_ = 0;
};

}  // namespace raypoint::core
