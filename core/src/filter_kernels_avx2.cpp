// SPDX-License-Identifier: MIT
// AVX2 kernels of the Poisson-disk filter's interior, compiled per function (target
// attribute) and only called when the CPU has AVX2. They read each tap's bytes with plain
// loads and shuffles, not gathers: AMD Zen microcodes vpgatherdd, which made a gathering kernel
// slower there than the SSE2 one. They store exactly what store_bgr() / store_yuv() would.

#include "filter_kernels.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define RAYPOINT_X86 1
#define RAYPOINT_AVX2 __attribute__((target("avx2")))
#endif

namespace raypoint::core {
namespace detail {

#if defined(RAYPOINT_X86)
namespace {

// A step covers eight working pixels; pixel k reads its 4-byte group (BGR and the next pixel's
// B, or a YUYV pair Y0 U Y1 V) of tap t at taps[t] + offsets[k]. The groups are loaded as two
// registers, `a` with pixels 0-1 in 128-bit lane 0 and 4-5 in lane 1, `b` with 2-3 and 6-7, each
// lane holding its first group at byte 0 and its second at byte `second`. widen() then spreads
// both groups to 16-bit lanes: the layout unpacklo / unpackhi of eight packed groups would give.
RAYPOINT_AVX2 __m256i widen_mask(int second) noexcept {
    const auto at = [second](int byte) {
        return static_cast<char>(byte < 4 ? byte : second + byte - 4);
    };
    const char z = -1;  // pshufb writes 0 for a set high bit
    return _mm256_setr_epi8(at(0), z, at(1), z, at(2), z, at(3), z, at(4), z, at(5), z, at(6), z,
                            at(7), z, at(0), z, at(1), z, at(2), z, at(3), z, at(4), z, at(5), z,
                            at(6), z, at(7), z);
}

RAYPOINT_AVX2 inline __m256i two_lanes(__m128i low, __m128i high) noexcept {
    return _mm256_inserti128_si256(_mm256_castsi128_si256(low), high, 1);
}

RAYPOINT_AVX2 inline __m128i load16(const std::uint8_t* at) noexcept {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
}

// Two groups, each from an 8-byte load (the first 4 bytes used), at bytes 0 and 8.
RAYPOINT_AVX2 inline __m128i two_groups(const std::uint8_t* first,
                                        const std::uint8_t* second) noexcept {
    return _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(first)),
                              _mm_loadl_epi64(reinterpret_cast<const __m128i*>(second)));
}

// Strided: centres step <= 12 bytes apart, so one 16-byte load holds a pixel's group and its
// neighbour's (at byte `step`): four loads a tap for eight pixels. Otherwise one 8-byte load a
// pixel.
template <bool Strided>
RAYPOINT_AVX2 inline void load_groups(const std::uint8_t* tap, const int* offsets, __m256i& a,
                                      __m256i& b) noexcept {
    if constexpr (Strided) {
        a = two_lanes(load16(tap + offsets[0]), load16(tap + offsets[4]));
        b = two_lanes(load16(tap + offsets[2]), load16(tap + offsets[6]));
    } else {
        a = two_lanes(two_groups(tap + offsets[0], tap + offsets[1]),
                      two_groups(tap + offsets[4], tap + offsets[5]));
        b = two_lanes(two_groups(tap + offsets[2], tap + offsets[3]),
                      two_groups(tap + offsets[6], tap + offsets[7]));
    }
}

// Whether a step at these offsets reads inside every tap's row: the strided loads end 16 bytes
// past pixel 6's group, the others 8 past pixel 7's.
template <bool Strided>
RAYPOINT_AVX2 inline bool reads_inside(const FilterRow& row, const int* offsets) noexcept {
    return Strided ? offsets[6] + 16 <= row.read_limit : offsets[7] + 8 <= row.read_limit;
}

// Eight BGR pixels from their tap sums (16-bit lanes B G R X, layout of load_groups()) to the
// colour row, the planes and grey. The second 16-byte colour store spills 4 bytes into columns
// x + 8 and x + 9, which the caller guarantees exist and are written later.
RAYPOINT_AVX2 void store_bgr_eight(const FilterRow& row, int x, __m256i low,
                                   __m256i high) noexcept {
    const __m256i half = _mm256_set1_epi16(poisson_disk_tap_count / 2);
    const __m256i weights =
        _mm256_setr_epi16(grey_weight_b, grey_weight_g, grey_weight_r, 0, grey_weight_b,
                          grey_weight_g, grey_weight_r, 0, grey_weight_b, grey_weight_g,
                          grey_weight_r, 0, grey_weight_b, grey_weight_g, grey_weight_r, 0);
    const __m256i grey_round = _mm256_set1_epi32(1 << (grey_shift - 1));
    // B G R X x 4 -> B G R x 4, per 128-bit lane.
    const __m256i drop_fourth =
        _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1, 0, 1, 2, 4, 5, 6,
                         8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
    const __m256i to_planes =
        _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, -1, -1, -1, -1, 0, 4, 8, 12, 1, 5,
                         9, 13, 2, 6, 10, 14, -1, -1, -1, -1);
    low = _mm256_srli_epi16(_mm256_add_epi16(low, half), tap_shift);
    high = _mm256_srli_epi16(_mm256_add_epi16(high, half), tap_shift);
    // Per 128-bit lane: pixels 0-3 (lane 1: 4-7) in order.
    __m256i grey =
        _mm256_hadd_epi32(_mm256_madd_epi16(low, weights), _mm256_madd_epi16(high, weights));
    grey = _mm256_srli_epi32(_mm256_add_epi32(grey, grey_round), grey_shift);
    grey = _mm256_packus_epi32(grey, grey);
    grey = _mm256_packus_epi16(grey, grey);
    store32(row.out.grey + x, _mm256_cvtsi256_si32(grey));
    store32(row.out.grey + x + 4, _mm256_extract_epi32(grey, 4));
    const __m256i pixels = _mm256_packus_epi16(low, high);
    const __m256i bytes = _mm256_shuffle_epi8(pixels, drop_fourth);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(row.out.color + x * 3),
                     _mm256_castsi256_si128(bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(row.out.color + x * 3 + 12),
                     _mm256_extracti128_si256(bytes, 1));
    // Planes: per 128-bit lane B0-3 G0-3 R0-3, then the two lanes' dwords side by side.
    const __m256i planes = _mm256_permutevar8x32_epi32(_mm256_shuffle_epi8(pixels, to_planes),
                                                       _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
    store64(row.out.blue + x, _mm256_extract_epi64(planes, 0));
    store64(row.out.green + x, _mm256_extract_epi64(planes, 1));
    store64(row.out.red + x, _mm256_extract_epi64(planes, 2));
}

// Whether a step of eight working pixels from x may run: inside the interior, its colour
// store's spill (columns x + 8, x + 9) inside the row, its loads inside every tap's row.
template <bool Strided>
RAYPOINT_AVX2 inline bool step_fits(const FilterRow& row, int x) noexcept {
    return x >= row.begin && x + 8 <= row.end && x + 10 <= row.width &&
           reads_inside<Strided>(row, row.centre_bytes + x);
}

// Steps of eight from row.begin, then, where the interior's width is not a multiple of eight,
// one last step ending at row.end: it filters again up to seven pixels the previous step did
// (the same sums, so the same bytes) instead of leaving them to the plain loops, which cost
// about 170 instructions a pixel. Returns the first working column left undone.
template <bool Strided, typename Step>
RAYPOINT_AVX2 inline int run_steps(const FilterRow& row, Step step) noexcept {
    int x = row.begin;
    for (; step_fits<Strided>(row, x); x += 8)
        step(x);
    if (x < row.end && step_fits<Strided>(row, row.end - 8)) {
        step(row.end - 8);
        x = row.end;
    }
    return x;
}

template <bool Strided>
RAYPOINT_AVX2 int filter_bgr_eight(const FilterRow& row) noexcept {
    const __m256i widen = widen_mask(Strided ? row.step_bytes : 8);
    return run_steps<Strided>(row, [&](int x) RAYPOINT_AVX2 {
        const int* offsets = row.centre_bytes + x;
        __m256i low = _mm256_setzero_si256();
        __m256i high = _mm256_setzero_si256();
        // Unrolled 16 times, GCC 12 hoists the loads and spills the widened taps to the stack
        // (two more memory operations a tap); by 4 it keeps the sums in registers.
#pragma GCC unroll 4
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            __m256i a;
            __m256i b;
            load_groups<Strided>(row.taps[t], offsets, a, b);
            low = _mm256_add_epi16(low, _mm256_shuffle_epi8(a, widen));
            high = _mm256_add_epi16(high, _mm256_shuffle_epi8(b, widen));
        }
        store_bgr_eight(row, x, low, high);
    });
}

// Tap sums [Y U ? V] (16-bit) to [Y - 16, U - 128, 1, V - 128] of their means, the terms of
// store_yuv()'s BT.601 sums (the 1 carries the rounding constant).
RAYPOINT_AVX2 __m256i yuv_terms(__m256i sums) noexcept {
    const __m256i means = _mm256_srli_epi16(
        _mm256_add_epi16(sums, _mm256_set1_epi16(poisson_disk_tap_count / 2)), tap_shift);
    const __m256i offsets =
        _mm256_setr_epi16(16, 128, 0, 128, 16, 128, 0, 128, 16, 128, 0, 128, 16, 128, 0, 128);
    const __m256i one = _mm256_setr_epi16(0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0);
    return _mm256_blend_epi16(_mm256_sub_epi16(means, offsets), one, 0x44);
}

// Eight pixels, per 128-bit lane B0-3 G0-3 R0-3 (lane 1: pixels 4-7), to the planes, the
// interleaved row and grey. The second colour store spills 4 bytes into columns x + 8, x + 9.
RAYPOINT_AVX2 void store_planar_eight(const FilterRow& row, int x, __m256i planar) noexcept {
    const __m256i planes =
        _mm256_permutevar8x32_epi32(planar, _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
    store64(row.out.blue + x, _mm256_extract_epi64(planes, 0));
    store64(row.out.green + x, _mm256_extract_epi64(planes, 1));
    store64(row.out.red + x, _mm256_extract_epi64(planes, 2));
    const __m256i interleave =
        _mm256_setr_epi8(0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11, -1, -1, -1, -1, 0, 4, 8, 1, 5, 9, 2,
                         6, 10, 3, 7, 11, -1, -1, -1, -1);
    const __m256i bytes = _mm256_shuffle_epi8(planar, interleave);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(row.out.color + x * 3),
                     _mm256_castsi256_si128(bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(row.out.color + x * 3 + 12),
                     _mm256_extracti128_si256(bytes, 1));
    // Grey from the clamped bytes, widened back to 32-bit lanes in pixel order.
    const __m256i zero = _mm256_setzero_si256();
    const __m256i words = _mm256_unpacklo_epi8(planar, zero);  // B0-3 G0-3 per lane
    const __m256i red = _mm256_unpackhi_epi8(planar, zero);    // R0-3 R0-3 per lane
    const __m256i blue32 = _mm256_unpacklo_epi16(words, zero);
    const __m256i green32 = _mm256_unpackhi_epi16(words, zero);
    const __m256i red32 = _mm256_unpacklo_epi16(red, zero);
    __m256i grey = _mm256_add_epi32(
        _mm256_add_epi32(_mm256_mullo_epi32(blue32, _mm256_set1_epi32(grey_weight_b)),
                         _mm256_mullo_epi32(green32, _mm256_set1_epi32(grey_weight_g))),
        _mm256_add_epi32(_mm256_mullo_epi32(red32, _mm256_set1_epi32(grey_weight_r)),
                         _mm256_set1_epi32(1 << (grey_shift - 1))));
    grey = _mm256_srli_epi32(grey, grey_shift);
    grey = _mm256_packus_epi32(grey, grey);
    grey = _mm256_packus_epi16(grey, grey);
    store32(row.out.grey + x, _mm256_cvtsi256_si32(grey));
    store32(row.out.grey + x + 4, _mm256_extract_epi32(grey, 4));
}

// YUYV tap sums split by the tap's parity (16-bit lanes Y0 U Y1 V, layout of load_groups()) to
// the stores of eight pixels.
RAYPOINT_AVX2 void store_yuyv_eight(const FilterRow& row, int x, __m256i even_low,
                                    __m256i even_high, __m256i odd_low, __m256i odd_high) noexcept {
    // store_yuv()'s BT.601 weights for [Y - 16, U - 128, 1, V - 128], 128 the rounding.
    const __m256i to_blue =
        _mm256_setr_epi16(298, 516, 128, 0, 298, 516, 128, 0, 298, 516, 128, 0, 298, 516, 128, 0);
    const __m256i to_green = _mm256_setr_epi16(298, -100, 128, -208, 298, -100, 128, -208, 298,
                                               -100, 128, -208, 298, -100, 128, -208);
    const __m256i to_red =
        _mm256_setr_epi16(298, 0, 128, 409, 298, 0, 128, 409, 298, 0, 128, 409, 298, 0, 128, 409);
    // Per pixel (64 bits): Y from the even taps' first and the odd taps' second place, U and V
    // from both; the means, less the offsets, with a constant 1 in the spare lane.
    const __m256i both = _mm256_add_epi16(even_low, odd_low);
    const __m256i both_high = _mm256_add_epi16(even_high, odd_high);
    const __m256i luma_low = _mm256_add_epi16(even_low, _mm256_srli_epi64(odd_low, 32));
    const __m256i luma_high = _mm256_add_epi16(even_high, _mm256_srli_epi64(odd_high, 32));
    const __m256i low = yuv_terms(_mm256_blend_epi16(both, luma_low, 0x11));
    const __m256i high = yuv_terms(_mm256_blend_epi16(both_high, luma_high, 0x11));
    // B, G, R of pixels 0-3 in 128-bit lane 0 and 4-7 in lane 1, each term pair summed.
    const __m256i blue = _mm256_srai_epi32(
        _mm256_hadd_epi32(_mm256_madd_epi16(low, to_blue), _mm256_madd_epi16(high, to_blue)), 8);
    const __m256i green = _mm256_srai_epi32(
        _mm256_hadd_epi32(_mm256_madd_epi16(low, to_green), _mm256_madd_epi16(high, to_green)), 8);
    const __m256i red = _mm256_srai_epi32(
        _mm256_hadd_epi32(_mm256_madd_epi16(low, to_red), _mm256_madd_epi16(high, to_red)), 8);
    // Saturating packs clamp to 0..255: per lane B0-3 G0-3 R0-3 R0-3.
    const __m256i planar =
        _mm256_packus_epi16(_mm256_packus_epi32(blue, green), _mm256_packus_epi32(red, red));
    store_planar_eight(row, x, planar);
}

// Centres of one parity: a tap's Y is the first or the second of its pair for every working
// pixel alike, so whole Y0 U Y1 V groups are summed split by the tap's parity, the Y picked at
// the end.
template <bool Strided>
RAYPOINT_AVX2 int filter_yuyv_eight(const FilterRow& row) noexcept {
    const __m256i widen = widen_mask(Strided ? row.step_bytes : 8);
    return run_steps<Strided>(row, [&](int x) RAYPOINT_AVX2 {
        const int* offsets = row.centre_bytes + x;
        __m256i even_low = _mm256_setzero_si256();
        __m256i even_high = _mm256_setzero_si256();
        __m256i odd_low = _mm256_setzero_si256();
        __m256i odd_high = _mm256_setzero_si256();
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            __m256i a;
            __m256i b;
            load_groups<Strided>(row.taps[t], offsets, a, b);
            const __m256i low = _mm256_shuffle_epi8(a, widen);
            const __m256i high = _mm256_shuffle_epi8(b, widen);
            if (((row.odd_taps >> t) & 1U) != 0) {
                odd_low = _mm256_add_epi16(odd_low, low);
                odd_high = _mm256_add_epi16(odd_high, high);
            } else {
                even_low = _mm256_add_epi16(even_low, low);
                even_high = _mm256_add_epi16(even_high, high);
            }
        }
        store_yuyv_eight(row, x, even_low, even_high, odd_low, odd_high);
    });
}

// A step of at most 12 bytes puts two neighbouring groups in one 16-byte load.
bool strided(const FilterRow& row) noexcept {
    return row.step_bytes > 0 && row.step_bytes <= 12;
}

}  // namespace

RAYPOINT_AVX2 int filter_bgr_avx2(const FilterRow& row) noexcept {
    return strided(row) ? filter_bgr_eight<true>(row) : filter_bgr_eight<false>(row);
}

RAYPOINT_AVX2 int filter_yuyv_avx2(const FilterRow& row) noexcept {
    return strided(row) ? filter_yuyv_eight<true>(row) : filter_yuyv_eight<false>(row);
}

#else

int filter_bgr_avx2(const FilterRow& row) noexcept {
    return row.begin;
}
int filter_yuyv_avx2(const FilterRow& row) noexcept {
    return row.begin;
}

#endif

}  // namespace detail
}  // namespace raypoint::core
