// SPDX-License-Identifier: MIT
// The difference image of preprocessing (paper 4.1): absolute difference, brightness
// compensation and the global movement value.

#include "raypoint/core/difference_stage.hpp"

#include <algorithm>

namespace raypoint::core {
namespace {

// |a - b| byte by byte; the unsigned form vectorizes.
void absolute_difference(const std::uint8_t* __restrict a, const std::uint8_t* __restrict b,
                         std::uint8_t* __restrict out, int length) noexcept {
    for (int i = 0; i < length; ++i)
        out[i] = static_cast<std::uint8_t>(std::max(a[i], b[i]) - std::min(a[i], b[i]));
}

using PartialHistograms = std::array<std::array<int, 256>, 4>;

// Four interleaved histograms: a still scene puts nearly every pixel in one bin, and
// incrementing one counter back to back waits for each previous increment.
void count(PartialHistograms& bins, const std::uint8_t* values, int length) noexcept {
    int x = 0;
    for (; x + 4 <= length; x += 4) {
        ++bins[0][values[x]];
        ++bins[1][values[x + 1]];
        ++bins[2][values[x + 2]];
        ++bins[3][values[x + 3]];
    }
    for (; x < length; ++x)
        ++bins[0][values[x]];
}

// count() of values[0], values[3], ... values[3 * (length - 1)].
void count_every_third(PartialHistograms& bins, const std::uint8_t* values, int length) noexcept {
    int x = 0;
    for (; x + 4 <= length; x += 4) {
        ++bins[0][values[3 * x]];
        ++bins[1][values[3 * x + 3]];
        ++bins[2][values[3 * x + 6]];
        ++bins[3][values[3 * x + 9]];
    }
    for (; x < length; ++x)
        ++bins[0][values[3 * x]];
}

std::array<int, 256> total(const PartialHistograms& bins) noexcept {
    std::array<int, 256> histogram{};
    for (int value = 0; value < 256; ++value) {
        histogram[value] = bins[0][value] + bins[1][value] + bins[2][value] + bins[3][value];
    }
    return histogram;
}

int offset_of(const std::array<int, 256>& histogram, int minima) noexcept {
    int distinct = 0;
    int largest = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (histogram[value] == 0) continue;
        ++distinct;
        largest = value;
    }
    return largest;
}

// The sum of max(0, value - offset) over the pixels the histogram counted; exact (an integer
// sum, at most 19,200 x 255 at the working size).
double compensated_sum(const std::array<int, 256>& histogram, int offset) noexcept {
    std::int64_t sum = 0;
    for (int value = offset + 1; value < 256; ++value)
        sum += static_cast<std::int64_t>(histogram[value]) * (value - offset);
    return static_cast<double>(sum);
}

}  // namespace

int brightness_offset(const cv::Mat& difference, int minima) noexcept {
    PartialHistograms bins{};
    for (int y = 0; y < difference.rows; ++y)
        count(bins, difference.ptr<std::uint8_t>(y), difference.cols);
    return offset_of(total(bins), minima);
}

DifferenceStage::DifferenceStage(const PreprocessSettings& settings)
    : channels_(settings.movement_source == EdgeSource::max_channel),
      minima_(settings.compensation_minima),
      channel_row_(static_cast<std::size_t>(settings.work_width) * 6) {
    difference_.create(settings.work_height, settings.work_width, CV_8U);
    difference_.setTo(cv::Scalar::all(0));
}

void DifferenceStage::reset() noexcept {
    difference_.setTo(cv::Scalar::all(0));
    movement_ = 0.0;
    offset_ = 0;
}

// The difference image is the grey one (paper 4.1): its centre of mass picks the target, and
// the target is what contrasts most. The movement value that starts a search may come from
// the largest per-channel difference instead, which also sees a skin hand move over a wall of
// its own brightness.
// One pass over the rows: the grey difference image and its histogram, and the per-channel
// difference's histogram; the offsets and the movement sums come from the histograms, so only
// the grey image is compensated in place.
void DifferenceStage::compute(const cv::Mat& grey, const cv::Mat& previous_grey,
                              const cv::Mat& color, const cv::Mat& previous_color) noexcept {
    const bool channels = channels_;  // a local: the stores below cannot change it
    const int width = difference_.cols;
    std::uint8_t* const channel_row = channel_row_.data();  // 3 * width, then 3 * width
    std::uint8_t* const strongest = channel_row + 3 * width;
    grey_bins_ = {};
    channel_bins_ = {};
    for (int y = 0; y < difference_.rows; ++y) {
        absolute_difference(grey.ptr<std::uint8_t>(y), previous_grey.ptr<std::uint8_t>(y),
                            difference_.ptr<std::uint8_t>(y), width);
        count(grey_bins_, difference_.ptr<std::uint8_t>(y), width);
        if (!channels) continue;
        absolute_difference(color.ptr<std::uint8_t>(y), previous_color.ptr<std::uint8_t>(y),
                            channel_row, 3 * width);
        // The max of each byte and the next two, contiguous so it vectorizes; pixel x's is at 3x.
        for (int i = 0; i + 2 < 3 * width; ++i)
            strongest[i] = std::max({channel_row[i], channel_row[i + 1], channel_row[i + 2]});
        count_every_third(channel_bins_, strongest, width);
    }
    const std::array<int, 256> grey_histogram = total(grey_bins_);
    offset_ = offset_of(grey_histogram, minima_);
    movement_ = compensated_sum(grey_histogram, offset_);
    if (channels) {
        const std::array<int, 256> channel_histogram = total(channel_bins_);
        movement_ = compensated_sum(channel_histogram, offset_of(channel_histogram, minima_));
    }
    const auto offset = static_cast<std::uint8_t>(offset_);
    for (int y = 0; y < difference_.rows; ++y) {
        std::uint8_t* row = difference_.ptr<std::uint8_t>(y);
        for (int x = 0; x < width; ++x)
            row[x] = static_cast<std::uint8_t>(row[x] > offset ? row[x] - offset : 0);
    }
}

}  // namespace raypoint::core
