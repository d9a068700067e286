// SPDX-License-Identifier: MIT
// The Poisson-disk filter and subsampling of preprocessing (paper 4.1), for BGR and YUYV input,
// with the grey image computed from the same sums.

#include "raypoint/core/filter_stage.hpp"

#include <algorithm>
#include <cstdint>

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
// and runs in the vector kernels of filter_kernels.cpp, the border after it.
void FilterStage::filter_bgr(const FrameView& frame) noexcept {
    const int* const centre_bytes = plan_.centre_bytes().data();
    for (int y = 0; y < plan_.working().height; ++y) {
        start_row(frame, y);
        const detail::FilterOutput target = output_row(y);
        for (int x = filter_interior(plan_.interior_begin(), target); x < plan_.interior_end();
             ++x) {
            unsigned b = 0, g = 0, r = 0;
            for (int t = 0; t < poisson_disk_tap_count; ++t) {
                const std::uint8_t* pixel = shifted_tap_pointers_[t] + centre_bytes[x];
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            detail::store_bgr(target, x, b, g, r);
        }
        filter_border(target);
    }
}

// The columns the interior leaves (clamped taps), after it: its kernels' stores may spill into
// the right border's first columns.
void FilterStage::filter_border(const detail::FilterOutput& target) const noexcept {
    const auto& groups = plan_.border_groups();
    const bool yuyv = plan_.format() == PixelFormat::yuyv;
    if (instructions_ == InstructionSet::avx2 &&
        detail::filter_border_avx2({tap_row_pointers_.data(), groups.data(),
                                    static_cast<int>(groups.size()), yuyv, target})) {
        return;
    }
    for (const FilterBorderGroup& group : groups) {
        for (int k = 0; k < group.count; ++k)
            filter_clamped(target, group.columns[k]);
    }
}

// One working column through the plan's clamped column tables (tap pointers not shifted).
void FilterStage::filter_clamped(const detail::FilterOutput& target, int x) const noexcept {
    const auto& taps = plan_.taps();
    unsigned first = 0, second = 0, third = 0;  // B G R, or Y U V
    if (plan_.format() == PixelFormat::yuyv) {
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const int column = taps[t].columns[x];
            const std::uint8_t* pair = tap_row_pointers_[t] + (column & ~1) * 2;
            first += pair[(column & 1) * 2];
            second += pair[1];
            third += pair[3];
        }
        detail::store_yuv(target, x, first, second, third);
        return;
    }
    for (int t = 0; t < poisson_disk_tap_count; ++t) {
        const std::uint8_t* pixel = tap_row_pointers_[t] + taps[t].columns[x] * 3;
        first += pixel[0];
        second += pixel[1];
        third += pixel[2];
    }
    detail::store_bgr(target, x, first, second, third);
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
    const detail::FilterRow row{shifted_tap_pointers_.data(),
                                plan_.centre_bytes().data(),
                                plan_.odd_taps(),
                                begin,
                                plan_.interior_end(),
                                plan_.working().width,
                                plan_.centre_step_bytes(),
                                plan_.read_limit(),
                                target,
                                fetch_,
                                fetch_end_,
                                fetch_lines_};
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

// Points each tap at its input row for working row y, also shifted by its column shift (the
// interior addresses a tap as shifted pointer + centre_bytes()[x]), and fetches the rows of
// the next.
void FilterStage::start_row(const FrameView& frame, int y) noexcept {
    const auto& taps = plan_.taps();
    for (std::size_t t = 0; t < tap_row_pointers_.size(); ++t) {
        tap_row_pointers_[t] =
            frame.data + static_cast<std::ptrdiff_t>(taps[t].rows[y]) * frame.stride;
        shifted_tap_pointers_[t] = tap_row_pointers_[t] + taps[t].shift_bytes;
    }
    if (y == 0) prefetch_rows(frame, 1);
    set_fetch(frame, y + 2);
    // The vector kernels spread the prefetches over their steps; the plain loops take them at
    // once.
    const bool kernels = plan_.format() == PixelFormat::bgr || plan_.uniform_parity();
    if (instructions_ == InstructionSet::scalar || !kernels) {
        prefetch(fetch_, fetch_end_);
        fetch_ = fetch_end_;
    }
}

// A camera frame arrives cold in memory; the taps read 16 rows at a time, too many streams
// for the hardware prefetcher, so the rows a later working row adds are fetched ahead: two
// working rows ahead, as one row's filtering is shorter than a fetch from memory. Into L2
// (T1), not L1: a working row's 120 lines at once are more misses than L1 tracks (likely
// prefetches waiting for a free L1 miss slot held up the loads); on AMD Zen 4 the filter took
// 20% less time with T1. The lines are the input rows working row `next_y` adds to the
// previous one's, as one span from the first's start to the last's end (64-byte aligned).
// The vector kernels issue them a few before each step: at once at the row's start, the prefetch
// instructions themselves stalled (on AMD Zen 4 a new frame took about 1.5x as long).
void FilterStage::set_fetch(const FrameView& frame, int next_y) noexcept {
    fetch_ = fetch_end_ = nullptr;
    if (next_y >= plan_.working().height) return;
    const int first = plan_.last_tap_row(next_y - 1) + 1;
    const int last = plan_.last_tap_row(next_y);
    if (first > last) return;
    const int bytes = frame.width * (frame.format == PixelFormat::bgr ? 3 : 2);
    // Back to its line's start: row `first` >= 1 starts at least a stride (>= 64 bytes) into
    // the frame, so this stays inside it.
    const std::uint8_t* start = frame.data + static_cast<std::ptrdiff_t>(first) * frame.stride;
    fetch_ = start - reinterpret_cast<std::uintptr_t>(start) % 64;
    fetch_end_ = frame.data + static_cast<std::ptrdiff_t>(last) * frame.stride + bytes;
    // Spread evenly over the interior's steps (eight working pixels with AVX2, four with SSE2),
    // four lines at a time.
    const long lines = (fetch_end_ - fetch_ + 63) / 64;
    const int step = instructions_ == InstructionSet::avx2 ? 8 : 4;
    const long steps = std::max(1, (plan_.interior_end() - plan_.interior_begin()) / step);
    fetch_lines_ = static_cast<int>((lines + 4 * steps - 1) / (4 * steps) * 4);
}

void FilterStage::prefetch(const std::uint8_t* begin, const std::uint8_t* end) noexcept {
#if defined(__SSE2__)
    for (; begin < end; begin += 64)
        _mm_prefetch(reinterpret_cast<const char*>(begin), _MM_HINT_T1);
#else
    (void)begin;
    (void)end;
#endif
}

void FilterStage::prefetch_rows(const FrameView& frame, int next_y) noexcept {
    set_fetch(frame, next_y);
    prefetch(fetch_, fetch_end_);
}

// YUYV: Y from the pixel itself, U and V from its pair; averaged as YUV, then converted to BGR
// (detail::store_yuv). The vector kernels need every interior centre of one parity (integer
// scales: 320, 640, 1280, 1920 wide to 160), so a tap's Y is at the same place of its pair.
void FilterStage::filter_yuyv(const FrameView& frame) noexcept {
    for (int y = 0; y < plan_.working().height; ++y) {
        start_row(frame, y);
        const detail::FilterOutput target = output_row(y);
        if (plan_.uniform_parity()) {
            const int done = filter_interior(plan_.interior_begin(), target);
            for (int x = done; x < plan_.interior_end(); ++x)
                filter_clamped(target, x);
        }
        filter_border(target);
    }
}

}  // namespace raypoint::core
