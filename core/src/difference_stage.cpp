// SPDX-License-Identifier: MIT
// The difference image of preprocessing (paper 4.1): absolute difference, brightness
// compensation (per band of rows, then the paper's offset) and the global movement value.

#include "raypoint/core/difference_stage.hpp"

#include "difference_kernels.hpp"

#include <algorithm>
#include <cstdlib>
#include <tuple>
#include <utility>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace raypoint::core {
namespace {

// Light ratios (current / previous) in 1/256: 0.4% steps, 1 grey level at 255.
constexpr int gain_bits = 8;
constexpr int gain_one = 1 << gain_bits;
// Ratios from 0.5 to 2, the extremes counted at the ends: mains flicker swings the light by
// +-30% at most, and a band whose light halves or doubles is not one to compensate finely.
constexpr int lowest_ratio = gain_one / 2;
constexpr int ratio_bins = 2 * gain_one - lowest_ratio;
// Working rows a light ratio is measured over: at 120 rows the flicker of 50 Hz mains read over
// 25 ms repeats every 48 rows, so a band of 4 is a 30 degree slice of it.
constexpr int band_rows = 4;
constexpr int ratio_step = 8;  // every eighth column: 80 ratios a band at 160x120
// Pixels this dark or saturated say little about the light: their ratio is noise or capped.
constexpr int darkest = 16;
constexpr int brightest = 254;
// A band whose light changed by at most this (in 1/gain_one: 0.8%, two grey levels at 255) is
// left to the paper's offset; when every band is, the relit difference is not computed.
constexpr int steady_light = 2;

// b x gain byte by byte, gain in 1/gain_one (below 2), rounded and capped at 255. The gain is
// applied in 1/128 (the product then fits 16 bits, 8 lanes a multiply): within a grey level.
void scale(const std::uint8_t* __restrict b, int gain, std::uint8_t* __restrict out,
           int length) noexcept {
    const auto g = static_cast<std::uint16_t>((gain + 1) >> 1);
    for (int i = 0; i < length; ++i) {
        const auto product = static_cast<std::uint16_t>(b[i] * g + 64U);
        out[i] = static_cast<std::uint8_t>(std::min<std::uint16_t>(product >> 7U, 255));
    }
}

struct LightRatio {
    unsigned usable;  // 1 when neither value is dark or saturated, else 0
    unsigned ratio;   // now / before in 1/gain_one, rounded
};

// One pixel's light ratio, by the reciprocal table (2^24 / before) instead of a division.
inline LightRatio light_ratio(unsigned now, unsigned before,
                              const std::array<std::uint32_t, 256>& reciprocal) noexcept {
    return {static_cast<unsigned>(now - darkest <= brightest - darkest) &
                static_cast<unsigned>(before - darkest <= brightest - darkest),
            (now * reciprocal[before] + 0x8000U) >> 16U};
}

// The median of the ratios current / previous over the pixels of rows [top, top + rows) (every
// ratio_step-th column) that are neither dark nor saturated in either frame, in 1/gain_one; 1
// when under a quarter of them are.
// The median: the target moving through the band changes fewer than half of its pixels.
int band_gain(const cv::Mat& grey, const cv::Mat& previous_grey, int top, int rows,
              const std::array<std::uint32_t, 256>& reciprocal) noexcept {
    // One bin past the ratios collects the pixels left out, so that the loop has no branch.
    std::array<int, ratio_bins + 1> bins{};
    for (int y = top; y < top + rows; ++y) {
        const std::uint8_t* now = grey.ptr<std::uint8_t>(y);
        const std::uint8_t* before = previous_grey.ptr<std::uint8_t>(y);
        for (int x = 0; x < grey.cols; x += ratio_step) {
            const auto [usable, ratio] = light_ratio(now[x], before[x], reciprocal);
            const unsigned bin = std::min(std::max(ratio, unsigned{lowest_ratio}) - lowest_ratio,
                                          unsigned{ratio_bins - 1});
            ++bins[usable != 0U ? bin : unsigned{ratio_bins}];
        }
    }
    const int sampled = rows * ((grey.cols + ratio_step - 1) / ratio_step);
    const int counted = sampled - bins[ratio_bins];
    if (4 * counted < sampled) return gain_one;
    int below = 0;
    for (int bin = 0; bin < ratio_bins; ++bin) {
        below += bins[bin];
        if (2 * below >= counted) return lowest_ratio + bin;
    }
    return gain_one;
}

#if defined(__x86_64__) && defined(__GNUC__)
struct StillCounts {
    unsigned counted = 0;
    unsigned below = 0;
    unsigned upto = 0;
};

// band_steady()'s three counts over a band's samples, eight at a time as 16-bit lanes (SSE2),
// summed once a band. For values both within [darkest, brightest] the rounded ratio of the
// reciprocal table is under gain_one - steady_light exactly when 512 now < 507 before, and at
// most gain_one + steady_light exactly when 512 now < 517 before (checked over every such
// pair): with e = before - now and g = 5 before, when 512 e > g and when 512 e + g > 0. e is
// clamped to [-32, 32] first, which keeps 512 e and 512 e + g within 16 bits and changes
// neither answer (g is at most 1275 < 512 x 32).
class StillCounter {
  public:
    // The samples of one row up to the last whole group of 32 columns; returns the first column
    // not counted.
    int count_row(const std::uint8_t* now, const std::uint8_t* before, int width) noexcept {
        static_assert(ratio_step == 8 && gain_one == 256 && steady_light == 2);
        int x = 0;
        for (; x + 8 * ratio_step <= width; x += 8 * ratio_step)
            count(eight_samples(now + x), eight_samples(before + x));
        if (x + 4 * ratio_step <= width) {
            const __m128i zero = _mm_setzero_si128();  // 0 is too dark: not counted
            count(_mm_packs_epi32(four_samples(now + x), zero),
                  _mm_packs_epi32(four_samples(before + x), zero));
            x += 4 * ratio_step;
        }
        return x;
    }

    StillCounts total() const noexcept { return {sum(counted_), sum(below_), sum(upto_)}; }

  private:
    // Bytes 0, 8, 16, 24 of `row` as 32-bit lanes.
    static __m128i four_samples(const std::uint8_t* row) noexcept {
        const __m128i sample = _mm_set1_epi64x(0xff);  // bytes 0 and 8 of 16: two samples
        const __m128i low =
            _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row)), sample);
        const __m128i high =
            _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + 16)), sample);
        return _mm_packs_epi32(low, high);  // int16 s, 0 pairs: the samples as int32 lanes
    }

    // Bytes 0, 8, ..., 56 of `row` as 16-bit lanes.
    static __m128i eight_samples(const std::uint8_t* row) noexcept {
        return _mm_packs_epi32(four_samples(row), four_samples(row + 32));
    }

    void count(__m128i a, __m128i b) noexcept {
        const __m128i too_dark = _mm_set1_epi16(darkest - 1);
        const __m128i too_bright = _mm_set1_epi16(brightest + 1);
        const __m128i usable = _mm_and_si128(
            _mm_and_si128(_mm_cmpgt_epi16(a, too_dark), _mm_cmplt_epi16(a, too_bright)),
            _mm_and_si128(_mm_cmpgt_epi16(b, too_dark), _mm_cmplt_epi16(b, too_bright)));
        const __m128i e = _mm_min_epi16(_mm_max_epi16(_mm_sub_epi16(b, a), _mm_set1_epi16(-32)),
                                        _mm_set1_epi16(32));
        const __m128i e512 = _mm_slli_epi16(e, 9);
        const __m128i g = _mm_add_epi16(_mm_slli_epi16(b, 2), b);
        counted_ = _mm_sub_epi16(counted_, usable);  // lanes of -1 where usable
        below_ = _mm_sub_epi16(below_, _mm_and_si128(usable, _mm_cmpgt_epi16(e512, g)));
        upto_ = _mm_sub_epi16(upto_, _mm_and_si128(usable, _mm_cmpgt_epi16(_mm_add_epi16(e512, g),
                                                                           _mm_setzero_si128())));
    }

    static unsigned sum(__m128i lanes) noexcept {
        lanes = _mm_madd_epi16(lanes, _mm_set1_epi16(1));  // 16-bit pairs to 32-bit lanes
        lanes = _mm_add_epi32(lanes, _mm_shuffle_epi32(lanes, 0x4e));
        lanes = _mm_add_epi32(lanes, _mm_shuffle_epi32(lanes, 0xb1));
        return static_cast<unsigned>(_mm_cvtsi128_si32(lanes));
    }

    __m128i counted_ = _mm_setzero_si128();
    __m128i below_ = _mm_setzero_si128();
    __m128i upto_ = _mm_setzero_si128();
};
#endif

// Whether band_gain() would return a gain within steady_light of 1, without its histogram: the
// median bin is within [gain_one - steady_light, gain_one + steady_light] exactly when fewer
// than half of the counted ratios lie below the range and at least half lie at or below its
// top (the clamp to the bins cannot move a ratio across either end: both are inside them).
// A band of still light, the common case, then costs three counters instead of a histogram
// of 385 bins cleared and walked to its median.
bool band_steady(const cv::Mat& grey, const cv::Mat& previous_grey, int top, int rows,
                 const std::array<std::uint32_t, 256>& reciprocal) noexcept {
    unsigned counted = 0;
    unsigned below = 0;  // usable ratios under gain_one - steady_light
    unsigned upto = 0;   // usable ratios at most gain_one + steady_light
#if defined(__x86_64__) && defined(__GNUC__)
    StillCounter vector;
#endif
    for (int y = top; y < top + rows; ++y) {
        const std::uint8_t* now = grey.ptr<std::uint8_t>(y);
        const std::uint8_t* before = previous_grey.ptr<std::uint8_t>(y);
        int x = 0;
#if defined(__x86_64__) && defined(__GNUC__)
        x = vector.count_row(now, before, grey.cols);
#endif
        for (; x < grey.cols; x += ratio_step) {
            const auto [usable, ratio] = light_ratio(now[x], before[x], reciprocal);
            counted += usable;
            below += usable & static_cast<unsigned>(ratio < unsigned{gain_one - steady_light});
            upto += usable & static_cast<unsigned>(ratio <= unsigned{gain_one + steady_light});
        }
    }
#if defined(__x86_64__) && defined(__GNUC__)
    const StillCounts counts = vector.total();
    counted += counts.counted;
    below += counts.below;
    upto += counts.upto;
#endif
    const auto sampled = static_cast<unsigned>(rows * ((grey.cols + ratio_step - 1) / ratio_step));
    if (4 * counted < sampled) return true;  // band_gain() returns gain_one
    return 2 * below < counted && 2 * upto >= counted;
}

}  // namespace

int brightness_offset(const cv::Mat& difference, int minima) noexcept {
    // The kernels read one run of bytes.
    const cv::Mat continuous = difference.isContinuous() ? difference : difference.clone();
    const std::uint8_t* values = continuous.data;
    const std::size_t pixels = continuous.total();
    const std::uint8_t smallest = pixels == 0 ? 255 : *std::min_element(values, values + pixels);
    return detail::difference_kernels::distinct_offset(values, pixels, smallest, minima);
}

DifferenceStage::DifferenceStage(const PreprocessSettings& settings)
    : channels_(settings.movement_source == EdgeSource::max_channel),
      rows_(settings.compensation == Compensation::rows),
      minima_(settings.compensation_minima),
      strongest_(static_cast<std::size_t>(settings.work_width) *
                 static_cast<std::size_t>(settings.work_height)),
      band_gains_(static_cast<std::size_t>((settings.work_height + band_rows - 1) / band_rows)),
      row_gains_(static_cast<std::size_t>(settings.work_height), gain_one),
      grey_row_(static_cast<std::size_t>(settings.work_width)) {
    if (rows_) {
        relit_.create(settings.work_height, settings.work_width, CV_8UC3);
        relit_difference_.create(settings.work_height, settings.work_width, CV_8U);
    }
    reciprocal_[0] = 0;
    for (std::uint32_t value = 1; value < reciprocal_.size(); ++value)
        reciprocal_[value] = ((std::uint32_t{gain_one} << 16U) + value / 2) / value;
    difference_.create(settings.work_height, settings.work_width, CV_8U);
    difference_.setTo(cv::Scalar::all(0));
}

void DifferenceStage::reset() noexcept {
    difference_.setTo(cv::Scalar::all(0));
    movement_ = 0.0;
    offset_ = 0;
    relit_current_ = false;
    light_change_ = 0.0;
    std::fill(row_gains_.begin(), row_gains_.end(), gain_one);
}

// Each band's gain at its middle row, linearly between the middles (in half rows, so that the
// middle of an even band is a whole number), held beyond the first and the last. Whether any
// band's light changed by more than steady_light.
bool DifferenceStage::estimate_row_gains(const cv::Mat& grey,
                                         const cv::Mat& previous_grey) noexcept {
    const int rows = grey.rows;
    const int bands = static_cast<int>(band_gains_.size());
    // Most frames have still light in every band: tell that cheaply, and compute the gains
    // only when a band's changed (from the first band again: all of them are interpolated).
    bool any_changed = false;
    for (int band = 0; band < bands && !any_changed; ++band) {
        const int top = band * band_rows;
        any_changed =
            !band_steady(grey, previous_grey, top, std::min(band_rows, rows - top), reciprocal_);
    }
    if (!any_changed) return false;
    bool changed = false;
    for (int band = 0; band < bands; ++band) {
        const int top = band * band_rows;
        band_gains_[band] =
            band_gain(grey, previous_grey, top, std::min(band_rows, rows - top), reciprocal_);
        changed = changed || std::abs(band_gains_[band] - gain_one) > steady_light;
    }
    if (!changed) return false;
    const auto middle = [](int band) { return 2 * band * band_rows + band_rows - 1; };
    for (int y = 0; y < rows; ++y) {
        const int at = 2 * y;
        int band = std::clamp((at - (band_rows - 1)) / (2 * band_rows), 0, bands - 1);
        if (at < middle(0) || band + 1 >= bands) {
            row_gains_[y] = band_gains_[band];
            continue;
        }
        const int span = 2 * band_rows;
        const int into = at - middle(band);
        row_gains_[y] =
            (band_gains_[band] * (span - into) + band_gains_[band + 1] * into + span / 2) / span;
    }
    return true;
}

// The difference image is the grey one (paper 4.1): its centre of mass picks the target, and
// the target is what contrasts most. The movement value that starts a search may come from
// the largest per-channel difference instead, which also sees a skin hand move over a wall of
// its own brightness.
// The grey difference as it is (the paper's); under Compensation::rows the same with each row
// of the previous image relit, kept when it leaves less movement: a light change by band
// (flicker, gain) is explained by the ratios, an even offset (the paper's case) by the paper's
// compensation. Each candidate is compensated in place as its movement is summed; the
// per-channel maxima are only summed.
void DifferenceStage::compute(const cv::Mat& grey, const cv::Mat& previous_grey,
                              const cv::Mat& color, const cv::Mat& previous_color) noexcept {
    namespace kernels = detail::difference_kernels;
    const bool channels = channels_;  // a local: the stores below cannot change it
    const int width = difference_.cols;
    const int height = difference_.rows;
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    // The offset from the uncompensated image, then the image compensated in place with its
    // sum; a relit candidate that loses is scratch. An offset of 0 (a still scene under still
    // light, most of all) leaves every pixel as is.
    const auto compensated = [this, pixels](cv::Mat& difference, std::uint8_t smallest) {
        const int offset = kernels::distinct_offset(difference.data, pixels, smallest, minima_);
        const auto subtrahend = static_cast<std::uint8_t>(offset);
        const std::int64_t sum = offset == 0
                                     ? kernels::compensated_sum(difference.data, pixels, 0)
                                     : kernels::compensate(difference.data, pixels, subtrahend);
        return std::pair{offset, static_cast<double>(sum)};
    };
    std::uint8_t smallest = 255;
    for (int y = 0; y < height; ++y) {
        smallest = kernels::absolute_difference(grey.ptr<std::uint8_t>(y),
                                                previous_grey.ptr<std::uint8_t>(y),
                                                difference_.ptr<std::uint8_t>(y), width, smallest);
    }
    std::tie(offset_, movement_) = compensated(difference_, smallest);
    relit_current_ = false;
    light_change_ = 0.0;
    if (rows_ && estimate_row_gains(grey, previous_grey)) {
        std::uint8_t* const grey_row = grey_row_.data();
        smallest = 255;
        for (int y = 0; y < height; ++y) {
            scale(previous_grey.ptr<std::uint8_t>(y), row_gains_[y], grey_row, width);
            smallest = kernels::absolute_difference(grey.ptr<std::uint8_t>(y), grey_row,
                                                    relit_difference_.ptr<std::uint8_t>(y), width,
                                                    smallest);
        }
        const auto [offset, movement] = compensated(relit_difference_, smallest);
        if (movement < movement_) {
            std::swap(difference_, relit_difference_);
            offset_ = offset;
            movement_ = movement;
            relit_current_ = true;
            // The change every band shares, in one direction: a gain or exposure jump lights the
            // whole picture alike, flicker's bands go brighter and darker by turns.
            int brighter = gain_one;
            int darker = gain_one;
            for (const int gain : band_gains_) {
                brighter = std::min(brighter, gain - gain_one);
                darker = std::min(darker, gain_one - gain);
            }
            light_change_ = static_cast<double>(std::max({brighter, darker, 0})) / gain_one;
        }
    }
    if (!channels && !relit_current_) return;
    smallest = 255;
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* color_before = previous_color.ptr<std::uint8_t>(y);
        if (relit_current_) {
            // Flicker changes every channel alike: the grey image's gains serve them. The
            // colour validation reads this image too (previous_color_relit()).
            scale(color_before, row_gains_[y], relit_.ptr<std::uint8_t>(y), 3 * width);
            color_before = relit_.ptr<std::uint8_t>(y);
        }
        if (!channels) continue;
        smallest = kernels::strongest_channel(color.ptr<std::uint8_t>(y), color_before,
                                              strongest_.data() + y * width, width, smallest);
    }
    if (channels) {
        const int offset = kernels::distinct_offset(strongest_.data(), pixels, smallest, minima_);
        movement_ = static_cast<double>(
            kernels::compensated_sum(strongest_.data(), pixels, static_cast<std::uint8_t>(offset)));
    }
}

}  // namespace raypoint::core
