// SPDX-License-Identifier: MIT
#pragma once
// Vector kernels of the Poisson-disk filter's interior (filter_stage.cpp), and the pixel
// arithmetic every path shares, so the scalar, SSE2 and AVX2 paths give identical images.

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "raypoint/core/filter_plan.hpp"
#include "raypoint/core/poisson_disk.hpp"

namespace raypoint::core::detail {

// The mean of the 16 taps with rounding: (sum + 8) / 16 as a shift.
constexpr int tap_shift = 4;
static_assert(1 << tap_shift == poisson_disk_tap_count);
constexpr unsigned tap_mean(unsigned sum) noexcept {
    return (sum + poisson_disk_tap_count / 2) >> tap_shift;
}

// BT.601 luma with OpenCV's cv::COLOR_BGR2GRAY fixed-point weights for 8-bit images (0.299,
// 0.587, 0.114 in 15-bit fixed point, rounded): equal to cvtColor on all 2^24 colours.
constexpr int grey_weight_b = 3735;
constexpr int grey_weight_g = 19235;
constexpr int grey_weight_r = 9798;
constexpr int grey_shift = 15;
constexpr std::uint8_t grey_of(unsigned b, unsigned g, unsigned r) noexcept {
    return static_cast<std::uint8_t>(
        (b * grey_weight_b + g * grey_weight_g + r * grey_weight_r + (1U << (grey_shift - 1))) >>
        grey_shift);
}

// One row of the working images the filter writes: interleaved BGR, grey, and B, G, R apart
// (the planes keep the Sobel loops contiguous).
struct FilterOutput {
    std::uint8_t* color;
    std::uint8_t* grey;
    std::uint8_t* blue;
    std::uint8_t* green;
    std::uint8_t* red;

    void store(int x, unsigned b, unsigned g, unsigned r) const noexcept {
        color[x * 3 + 0] = static_cast<std::uint8_t>(b);
        color[x * 3 + 1] = static_cast<std::uint8_t>(g);
        color[x * 3 + 2] = static_cast<std::uint8_t>(r);
        blue[x] = static_cast<std::uint8_t>(b);
        green[x] = static_cast<std::uint8_t>(g);
        red[x] = static_cast<std::uint8_t>(r);
        grey[x] = grey_of(b, g, r);
    }
};

// One working row's interior, where no tap needs clamping.
struct FilterRow {
    // Per tap, its input row with the tap's column shift applied (BGR: dx * 3 bytes; YUYV with
    // centres of parity p: ((p + dx) & ~1) * 2 bytes, the start of the tap's Y0 U Y1 V group).
    const std::uint8_t* const* taps;
    const int* centre_bytes;  // per working column, the byte offset of its centre (group)
    std::uint32_t odd_taps;   // YUYV: bit t set where tap t's Y is the second of its pair
    int begin;                // first working column to do
    int end;                  // one past the last interior column
    int width;                // working width: stores may spill into columns still to come
    // Bytes between neighbouring interior centres when the step is the same everywhere (BGR
    // 640 wide: 12; YUYV 640 wide: 8, 320 wide: 4), else 0.
    int step_bytes;
    // A read of n bytes at a tap's pointer + o stays inside every tap's input row when
    // o + n <= read_limit: the row's bytes less the largest tap shift.
    int read_limit;
    FilterOutput out;
    // Input lines (64 bytes each) to prefetch into L2 while filtering: from `fetch` (64-byte
    // aligned) to `fetch_end`, `fetch_lines` (a multiple of 4) before each step, the rest
    // after the last.
    const std::uint8_t* fetch;
    const std::uint8_t* fetch_end;
    int fetch_lines;
};

// The working columns outside the interior (FilterPlan::border_groups()).
struct FilterBorder {
    const std::uint8_t* const* taps;  // per tap, its input row (no column shift)
    const FilterBorderGroup* groups;
    int group_count;
    bool yuyv;
    FilterOutput out;
};

// Prefetches into L2 up to `lines` (a multiple of 4) of the row's lines from `at`, four at a
// time, stopping at row.fetch_end (the last four may pass it by up to three lines, which a
// prefetch may: it never faults); returns where the next prefetch starts.
constexpr int all_lines = 1 << 30;
inline const std::uint8_t* prefetch_lines(const FilterRow& row, const std::uint8_t* at,
                                          int lines) noexcept {
#if defined(__SSE2__)
    for (; lines > 0 && at < row.fetch_end; lines -= 4, at += 4 * 64) {
        _mm_prefetch(reinterpret_cast<const char*>(at), _MM_HINT_T1);
        _mm_prefetch(reinterpret_cast<const char*>(at + 64), _MM_HINT_T1);
        _mm_prefetch(reinterpret_cast<const char*>(at + 2 * 64), _MM_HINT_T1);
        _mm_prefetch(reinterpret_cast<const char*>(at + 3 * 64), _MM_HINT_T1);
    }
    return at;
#else
    (void)row;
    (void)lines;
    return at;
#endif
}

// Unaligned 4- and 8-byte accesses without aliasing concerns (they compile to one move).
inline int load32(const std::uint8_t* at) noexcept {
    int value = 0;
    std::memcpy(&value, at, 4);
    return value;
}
inline void store32(std::uint8_t* at, int value) noexcept {
    std::memcpy(at, &value, 4);
}
inline void store64(std::uint8_t* at, long long value) noexcept {
    std::memcpy(at, &value, 8);
}

// Each returns the first working column it left undone (a multiple of its step from begin).
int filter_bgr_sse2(const FilterRow& row) noexcept;
int filter_yuyv_sse2(const FilterRow& row) noexcept;
int filter_bgr_avx2(const FilterRow& row) noexcept;
int filter_yuyv_avx2(const FilterRow& row) noexcept;
// Returns false where the CPU's x86 kernels are not compiled (the caller loops instead).
bool filter_border_avx2(const FilterBorder& border) noexcept;

// YUYV sums of 16 taps, Y from each tap's own pixel, U and V from its pair, to a BGR pixel and
// its grey: averaged as YUV, then BT.601 limited range, the usual meaning of V4L2's YUYV.
inline void store_yuv(const FilterOutput& out, int x, unsigned sum_y, unsigned sum_u,
                      unsigned sum_v) noexcept {
    const auto clamp_byte = [](int value) {
        return static_cast<unsigned>(value < 0 ? 0 : (value > 255 ? 255 : value));
    };
    const int luma = static_cast<int>(tap_mean(sum_y)) - 16;
    const int u = static_cast<int>(tap_mean(sum_u)) - 128;
    const int v = static_cast<int>(tap_mean(sum_v)) - 128;
    const int scaled = 298 * luma + 128;
    const unsigned b = clamp_byte((scaled + 516 * u) >> 8);
    const unsigned g = clamp_byte((scaled - 100 * u - 208 * v) >> 8);
    const unsigned r = clamp_byte((scaled + 409 * v) >> 8);
    out.store(x, b, g, r);
}

inline void store_bgr(const FilterOutput& out, int x, unsigned sum_b, unsigned sum_g,
                      unsigned sum_r) noexcept {
    out.store(x, tap_mean(sum_b), tap_mean(sum_g), tap_mean(sum_r));
}

}  // namespace raypoint::core::detail
