// SPDX-License-Identifier: MIT
// AVX2 kernels of the Poisson-disk filter's interior, compiled per function (target
// attribute) and only called when the CPU has AVX2. They read each tap's bytes with plain
// loads and shuffles, not gathers: AMD Zen microcodes vpgatherdd, which made a gathering kernel
// slower there than the SSE2 one. They store exactly what store_bgr() / store_yuv() would.

#include "filter_kernels.hpp"

#include <cstring>

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

// A register's high quadword to 8 bytes at any address. Through a local double and memcpy:
// _mm_storeh_pd on the byte address itself would be a store through a misaligned double*,
// undefined behaviour (UBSan stops on it); GCC still emits one vmovhpd to the destination.
RAYPOINT_AVX2 inline void store_high(std::uint8_t* at, __m128i value) noexcept {
    double high = 0.0;
    _mm_storeh_pd(&high, _mm_castsi128_pd(value));
    std::memcpy(at, &high, sizeof high);
}

// Eight working pixels of each plane and of grey (quadwords B, G, R, grey) to their rows.
RAYPOINT_AVX2 inline void store_quadwords(const FilterOutput& out, int x, __m256i planes) noexcept {
    const __m128i blue_green = _mm256_castsi256_si128(planes);
    const __m128i red_grey = _mm256_extracti128_si256(planes, 1);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out.blue + x), blue_green);
    store_high(out.green + x, blue_green);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out.red + x), red_grey);
    store_high(out.grey + x, red_grey);
}

// Eight BGR pixels from their tap sums (16-bit lanes B G R X, layout of load_groups()) to the
// colour row, the planes and grey. The second 16-byte colour store spills 4 bytes into columns
// x + 8 and x + 9, which the caller guarantees exist and are written later. Grey joins the
// planes in one register (per 128-bit lane B0-3 G0-3 R0-3 grey0-3), so one permute puts each
// image's eight bytes in a quadword, stored straight from the two 128-bit halves.
RAYPOINT_AVX2 void store_bgr_eight(const FilterRow& row, int x, __m256i low,
                                   __m256i high) noexcept {
    const FilterOutput out = row.out;  // in registers: the byte stores below could alias `row`
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
    // The low byte of each 32-bit grey value (at most 255) to the lane's last four bytes.
    const __m256i grey_last =
        _mm256_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4, 8, 12, -1, -1, -1,
                         -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4, 8, 12);
    low = _mm256_srli_epi16(_mm256_add_epi16(low, half), tap_shift);
    high = _mm256_srli_epi16(_mm256_add_epi16(high, half), tap_shift);
    // Per 128-bit lane: pixels 0-3 (lane 1: 4-7) in order.
    __m256i grey =
        _mm256_hadd_epi32(_mm256_madd_epi16(low, weights), _mm256_madd_epi16(high, weights));
    grey = _mm256_srli_epi32(_mm256_add_epi32(grey, grey_round), grey_shift);
    const __m256i pixels = _mm256_packus_epi16(low, high);
    const __m256i bytes = _mm256_shuffle_epi8(pixels, drop_fourth);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out.color + x * 3), _mm256_castsi256_si128(bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out.color + x * 3 + 12),
                     _mm256_extracti128_si256(bytes, 1));
    const __m256i planes =
        _mm256_permutevar8x32_epi32(_mm256_or_si256(_mm256_shuffle_epi8(pixels, to_planes),
                                                    _mm256_shuffle_epi8(grey, grey_last)),
                                    _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
    store_quadwords(out, x, planes);
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
// The prefetches of the rows a later working row adds are spread over the steps: issued all
// at once at the row's start, the prefetch instructions themselves stalled (about 120 lines at
// 640x480 BGR, more misses than the core tracks at a time).
template <bool Strided, typename Step>
RAYPOINT_AVX2 inline int run_steps(const FilterRow& row, Step step) noexcept {
    const std::uint8_t* fetch = row.fetch;
    int x = row.begin;
    for (; step_fits<Strided>(row, x); x += 8) {
        fetch = prefetch_lines(row, fetch, row.fetch_lines);
        step(x);
    }
    if (x < row.end && step_fits<Strided>(row, row.end - 8)) {
        step(row.end - 8);
        x = row.end;
    }
    prefetch_lines(row, fetch, all_lines);
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
// Grey takes the lanes' last four bytes, so one permute puts each image's eight bytes in a
// quadword (as store_bgr_eight()).
RAYPOINT_AVX2 void store_planar_eight(const FilterRow& row, int x, __m256i planar) noexcept {
    const FilterOutput out = row.out;  // in registers: the byte stores below could alias `row`
    const __m256i interleave =
        _mm256_setr_epi8(0, 4, 8, 1, 5, 9, 2, 6, 10, 3, 7, 11, -1, -1, -1, -1, 0, 4, 8, 1, 5, 9, 2,
                         6, 10, 3, 7, 11, -1, -1, -1, -1);
    const __m256i bytes = _mm256_shuffle_epi8(planar, interleave);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out.color + x * 3), _mm256_castsi256_si128(bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out.color + x * 3 + 12),
                     _mm256_extracti128_si256(bytes, 1));
    // Grey from the clamped bytes in 32-bit lanes in pixel order: B and G as 16-bit pairs and R
    // alone, each pair's products summed by one vpmaddwd (the weights fit 16 bits).
    const __m256i blue_green_words = _mm256_shuffle_epi8(
        planar, _mm256_setr_epi8(0, -1, 4, -1, 1, -1, 5, -1, 2, -1, 6, -1, 3, -1, 7, -1, 0, -1, 4,
                                 -1, 1, -1, 5, -1, 2, -1, 6, -1, 3, -1, 7, -1));
    const __m256i red_words = _mm256_shuffle_epi8(
        planar, _mm256_setr_epi8(8, -1, -1, -1, 9, -1, -1, -1, 10, -1, -1, -1, 11, -1, -1, -1, 8,
                                 -1, -1, -1, 9, -1, -1, -1, 10, -1, -1, -1, 11, -1, -1, -1));
    __m256i grey = _mm256_add_epi32(
        _mm256_add_epi32(
            _mm256_madd_epi16(blue_green_words,
                              _mm256_set1_epi32((grey_weight_g << 16) | grey_weight_b)),
            _mm256_madd_epi16(red_words, _mm256_set1_epi32(grey_weight_r))),
        _mm256_set1_epi32(1 << (grey_shift - 1)));
    grey = _mm256_srli_epi32(grey, grey_shift);
    const __m256i grey_last =
        _mm256_setr_epi8(-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4, 8, 12, -1, -1, -1,
                         -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4, 8, 12);
    const __m256i planes = _mm256_permutevar8x32_epi32(
        _mm256_blend_epi32(planar, _mm256_shuffle_epi8(grey, grey_last), 0x88),
        _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
    store_quadwords(out, x, planes);
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

// Four clamped columns a group: per tap, the four loads the plan gives, packed into one 128-bit
// register, copied to both lanes, and widened by the plan's shuffle to [B G R 0] (YUYV
// [Y U V 0]) per column, the 16 taps summed in 16-bit lanes. About 12 instructions a tap for
// four columns, against about 9 a tap and column for the plain loop.
RAYPOINT_AVX2 bool filter_border_avx2(const FilterBorder& border) noexcept {
    for (int g = 0; g < border.group_count; ++g) {
        const FilterBorderGroup& group = border.groups[g];
        __m256i sums = _mm256_setzero_si256();
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const std::uint8_t* tap = border.taps[t];
            const FilterBorderGroup::Tap& plan = group.taps[t];
            __m128i packed = _mm_cvtsi32_si128(load32(tap + plan.loads[0]));
            packed = _mm_insert_epi32(packed, load32(tap + plan.loads[1]), 1);
            packed = _mm_insert_epi32(packed, load32(tap + plan.loads[2]), 2);
            packed = _mm_insert_epi32(packed, load32(tap + plan.loads[3]), 3);
            const __m256i select =
                _mm256_loadu_si256(reinterpret_cast<const __m256i*>(plan.select.data()));
            sums = _mm256_add_epi16(
                sums, _mm256_shuffle_epi8(_mm256_broadcastsi128_si256(packed), select));
        }
        alignas(32) std::uint16_t lanes[16];
        _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), sums);
        for (int k = 0; k < group.count; ++k) {
            const std::uint16_t* sum = lanes + 4 * k;
            if (border.yuyv) {
                store_yuv(border.out, group.columns[k], sum[0], sum[1], sum[2]);
            } else {
                store_bgr(border.out, group.columns[k], sum[0], sum[1], sum[2]);
            }
        }
    }
    return true;
}

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
bool filter_border_avx2(const FilterBorder&) noexcept {
    return false;
}

#endif

}  // namespace detail
}  // namespace raypoint::core
