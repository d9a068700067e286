// SPDX-License-Identifier: MIT
// The Poisson-disk filter and subsampling of preprocessing (paper 4.1), for BGR and YUYV input,
// with the grey image computed from the same sums.

#include "raypoint/core/filter_stage.hpp"

#include <algorithm>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "filter_kernels.hpp"

namespace raypoint::core {

FilterStage::FilterStage(const PreprocessSettings& settings, InstructionSet instructions)
    : instructions_(instructions),
      plan_(cv::Size(settings.work_width, settings.work_height), settings.filter_radius) {
    const cv::Size size = plan_.working();
    for (int i = 0; i < 2; ++i) {
        color_[i].create(size, CV_8UC3);
        color_[i].setTo(cv::Scalar::all(0));
        gray_[i].create(size, CV_8U);
        gray_[i].setTo(cv::Scalar::all(0));
    }
    planes_.create(size.height * 3, size.width, CV_8U);
}

bool FilterStage::apply(const FrameView& frame) noexcept {
    const cv::Size working = plan_.working();
    const int bytes_per_pixel = frame.format == PixelFormat::bgr ? 3 : 2;
    if (frame.data == nullptr || frame.width < working.width || frame.height < working.height ||
        frame.stride < frame.width * bytes_per_pixel ||
        (frame.format == PixelFormat::yuyv && frame.width % 2 != 0)) {
        return false;
    }
    if (!plan_.matches(frame)) {
        filtered_ = 0;  // a new geometry has no comparable previous frame
        try {
            plan_.build(frame.width, frame.height, frame.format);
        } catch (...) {  // out of memory while setting up a new geometry: skip the frame
            return false;
        }
    }
    current_ = 1 - current_;
    switch (frame.format) {
        case PixelFormat::bgr:
            filter_bgr(frame);
            break;
        case PixelFormat::yuyv:
            filter_yuyv(frame);
            break;
    }
    ++filtered_;
    return true;
}

// The filter is evaluated only at the working pixels' centres: filtering the whole frame and
// then subsampling gives the same values at 16x the cost for 640x480. Working pixel outside,
// taps inside, so the sums stay in registers; the interior skips the clamped column tables
// and runs in the vector kernels of filter_kernels.cpp.
void FilterStage::filter_bgr(const FrameView& frame) noexcept {
    const auto& taps = plan_.taps();
    const int* const centre_bytes = plan_.centre_bytes().data();
    const int width = plan_.working().width;
    const int interior_begin = plan_.interior_begin();
    const int interior_end = plan_.interior_end();
    for (int y = 0; y < plan_.working().height; ++y) {
        start_row(frame, y);
        const detail::FilterOutput target = output_row(y);
        const auto clamped = [&](int x) {
            unsigned b = 0, g = 0, r = 0;
            for (int t = 0; t < poisson_disk_tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + taps[t].columns[x] * 3;
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            detail::store_bgr(target, x, b, g, r);
        };
        int x = 0;
        for (; x < interior_begin; ++x)
            clamped(x);
        shift_taps(1);
        x = filter_interior(x, target);
        for (; x < interior_end; ++x) {
            unsigned b = 0, g = 0, r = 0;
            for (int t = 0; t < poisson_disk_tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + centre_bytes[x];
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            detail::store_bgr(target, x, b, g, r);
        }
        shift_taps(-1);
        for (x = std::max(interior_end, interior_begin); x < width; ++x)
            clamped(x);
    }
}

detail::FilterOutput FilterStage::output_row(int y) noexcept {
    const int height = plan_.working().height;
    return {color_[current_].ptr<std::uint8_t>(y), gray_[current_].ptr<std::uint8_t>(y),
            planes_.ptr<std::uint8_t>(y), planes_.ptr<std::uint8_t>(height + y),
            planes_.ptr<std::uint8_t>(2 * height + y)};
}

// The vector kernels over the interior from working column `begin` (the taps shifted);
// returns the first column they left for the plain loops.
int FilterStage::filter_interior(int begin, const detail::FilterOutput& target) const noexcept {
    const detail::FilterRow row{tap_row_pointers_.data(),
                                plan_.centre_bytes().data(),
                                plan_.odd_taps(),
                                begin,
                                plan_.interior_end(),
                                plan_.working().width,
                                plan_.centre_step_bytes(),
                                plan_.read_limit(),
                                target};
    const bool bgr = plan_.format() == PixelFormat::bgr;
    switch (instructions_) {
        case InstructionSet::avx2:
            return bgr ? detail::filter_bgr_avx2(row) : detail::filter_yuyv_avx2(row);
        case InstructionSet::sse2:
            return bgr ? detail::filter_bgr_sse2(row) : detail::filter_yuyv_sse2(row);
        case InstructionSet::scalar:
            break;
    }
    return begin;
}

// Moves every tap's row pointer by its column shift (sign 1) or back (-1): the interior
// addresses a tap as row pointer + centre_bytes()[x].
void FilterStage::shift_taps(int sign) noexcept {
    const auto& taps = plan_.taps();
    for (std::size_t t = 0; t < tap_row_pointers_.size(); ++t)
        tap_row_pointers_[t] += sign * taps[t].shift_bytes;
}

// Points each tap at its input row for working row y, and fetches the rows of the next.
void FilterStage::start_row(const FrameView& frame, int y) noexcept {
    const auto& taps = plan_.taps();
    for (std::size_t t = 0; t < tap_row_pointers_.size(); ++t) {
        tap_row_pointers_[t] =
            frame.data + static_cast<std::ptrdiff_t>(taps[t].rows[y]) * frame.stride;
    }
    if (y == 0) prefetch_rows(frame, 1);
    prefetch_rows(frame, y + 2);
}

// A camera frame arrives cold in memory; the taps read 16 rows at a time, too many streams
// for the hardware prefetcher, so the rows a later working row adds are fetched ahead: two
// working rows ahead, as one row's filtering is shorter than a fetch from memory. Into L2
// (T1), not L1: a working row's 120 lines at once are more misses than L1 tracks (likely
// prefetches waiting for a free L1 miss slot held up the loads); on AMD Zen 4 the filter took
// 20% less time with T1.
void FilterStage::prefetch_rows(const FrameView& frame, int next_y) const noexcept {
#if defined(__SSE2__)
    if (next_y >= plan_.working().height) return;
    const int first = plan_.last_tap_row(next_y - 1) + 1;
    const int last = plan_.last_tap_row(next_y);
    const int bytes = frame.width * (frame.format == PixelFormat::bgr ? 3 : 2);
    for (int row = first; row <= last; ++row) {
        const std::uint8_t* start = frame.data + static_cast<std::ptrdiff_t>(row) * frame.stride;
        for (int offset = 0; offset < bytes; offset += 64) {
            _mm_prefetch(reinterpret_cast<const char*>(start + offset), _MM_HINT_T1);
        }
    }
#else
    (void)frame;
    (void)next_y;
#endif
}

// YUYV: Y from the pixel itself, U and V from its pair; averaged as YUV, then converted to BGR
// (detail::store_yuv). The vector kernels need every interior centre of one parity (integer
// scales: 320, 640, 1280, 1920 wide to 160), so a tap's Y is at the same place of its pair.
void FilterStage::filter_yuyv(const FrameView& frame) noexcept {
    const auto& taps = plan_.taps();
    const int width = plan_.working().width;
    for (int y = 0; y < plan_.working().height; ++y) {
        start_row(frame, y);
        const detail::FilterOutput target = output_row(y);
        const auto clamped = [&](int x) {
            unsigned sum_y = 0, sum_u = 0, sum_v = 0;
            for (int t = 0; t < poisson_disk_tap_count; ++t) {
                const int column = taps[t].columns[x];
                const std::uint8_t* pair = tap_row_pointers_[t] + (column & ~1) * 2;
                sum_y += pair[(column & 1) * 2];
                sum_u += pair[1];
                sum_v += pair[3];
            }
            detail::store_yuv(target, x, sum_y, sum_u, sum_v);
        };
        int x = 0;
        if (plan_.uniform_parity()) {
            for (; x < plan_.interior_begin(); ++x)
                clamped(x);
            shift_taps(1);
            x = filter_interior(x, target);
            shift_taps(-1);
        }
        for (; x < width; ++x)
            clamped(x);
    }
}

}  // namespace raypoint::core
