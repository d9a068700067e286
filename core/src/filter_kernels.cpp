// SPDX-License-Identifier: MIT
// SSE2 and AVX2 kernels of the Poisson-disk filter's interior. AVX2 is compiled per function
// (target attribute) and only called when the CPU has it (best_instruction_set()); SSE2 is
// part of x86-64. Both store exactly what store_bgr() / store_yuv() would.

#include "filter_kernels.hpp"

#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define RAYPOINT_X86 1
#endif

namespace raypoint::core {
namespace detail {

#if defined(RAYPOINT_X86)
namespace {

int load32(const std::uint8_t* at) noexcept {
    int value = 0;
    std::memcpy(&value, at, 4);
    return value;
}

void store32(std::uint8_t* at, int value) noexcept {
    std::memcpy(at, &value, 4);
}

void store64(std::uint8_t* at, long long value) noexcept {
    std::memcpy(at, &value, 8);
}

// Four BGR(X) tap sums, pixels 0-1 in `low` and 2-3 in `high` (16-bit lanes B G R X), to
// their means and grey. A pixel is stored as 4 bytes whose 4th the next one overwrites: the
// last spills into column x + 4, which the caller guarantees exists and is written later.
void store_four_bgr(const FilterRow& row, int x, __m128i low, __m128i high) noexcept {
    const __m128i half = _mm_set1_epi16(poisson_disk_tap_count / 2);
    low = _mm_srli_epi16(_mm_add_epi16(low, half), tap_shift);
    high = _mm_srli_epi16(_mm_add_epi16(high, half), tap_shift);
    const __m128i weights = _mm_setr_epi16(grey_weight_b, grey_weight_g, grey_weight_r, 0,
                                           grey_weight_b, grey_weight_g, grey_weight_r, 0);
    // 32-bit lanes b*wb + g*wg, r*wr per pixel; even lanes of both, plus odd lanes of both.
    const __m128 products_low = _mm_castsi128_ps(_mm_madd_epi16(low, weights));
    const __m128 products_high = _mm_castsi128_ps(_mm_madd_epi16(high, weights));
    const __m128i weighted_blue_green =
        _mm_castps_si128(_mm_shuffle_ps(products_low, products_high, _MM_SHUFFLE(2, 0, 2, 0)));
    const __m128i weighted_red =
        _mm_castps_si128(_mm_shuffle_ps(products_low, products_high, _MM_SHUFFLE(3, 1, 3, 1)));
    __m128i grey = _mm_add_epi32(_mm_add_epi32(weighted_blue_green, weighted_red),
                                 _mm_set1_epi32(1 << (grey_shift - 1)));
    grey = _mm_srli_epi32(grey, grey_shift);
    grey = _mm_packs_epi32(grey, grey);
    grey = _mm_packus_epi16(grey, grey);
    store32(row.out.grey + x, _mm_cvtsi128_si32(grey));
    const __m128i bytes = _mm_packus_epi16(low, high);  // B G R X of pixels 0-3
    alignas(16) std::uint8_t pixels[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(pixels), bytes);
    for (int k = 0; k < 4; ++k)
        std::memcpy(row.out.color + (x + k) * 3, pixels + 4 * k, 4);
    // Planes: each channel's byte of the four 32-bit pixels, packed down to four bytes.
    const __m128i byte_mask = _mm_set1_epi32(0xFF);
    const __m128i blue_green = _mm_packs_epi32(_mm_and_si128(bytes, byte_mask),
                                               _mm_and_si128(_mm_srli_epi32(bytes, 8), byte_mask));
    const __m128i red = _mm_and_si128(_mm_srli_epi32(bytes, 16), byte_mask);
    const __m128i planes = _mm_packus_epi16(blue_green, _mm_packs_epi32(red, red));
    store32(row.out.blue + x, _mm_cvtsi128_si32(planes));
    store32(row.out.green + x, _mm_cvtsi128_si32(_mm_srli_si128(planes, 4)));
    store32(row.out.red + x, _mm_cvtsi128_si32(_mm_srli_si128(planes, 8)));
}

}  // namespace

// Four working pixels a step: each tap's B, G, R (and the next pixel's B, ignored) are one
// 32-bit load widened to 16-bit lanes; 16 taps x 255 fit in 16 bits. The interior has a
// column to spare on the right, so the 4th byte is inside the frame.
int filter_bgr_sse2(const FilterRow& row) noexcept {
    const __m128i zero = _mm_setzero_si128();
    int x = row.begin;
    for (; x + 4 <= row.end && x + 4 < row.width; x += 4) {
        const int* centre = row.centre_bytes + x;
        __m128i low = zero;   // pixels x, x+1
        __m128i high = zero;  // pixels x+2, x+3
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const std::uint8_t* tap = row.taps[t];
            const __m128i packed = _mm_setr_epi32(load32(tap + centre[0]), load32(tap + centre[1]),
                                                  load32(tap + centre[2]), load32(tap + centre[3]));
            low = _mm_add_epi16(low, _mm_unpacklo_epi8(packed, zero));
            high = _mm_add_epi16(high, _mm_unpackhi_epi8(packed, zero));
        }
        store_four_bgr(row, x, low, high);
    }
    return x;
}

// Centres of one parity: a tap's Y is the first or the second of its pair for every working
// pixel alike, so whole Y0 U Y1 V groups are summed split by the tap's parity, the Y picked at the
// end.
int filter_yuyv_sse2(const FilterRow& row) noexcept {
    const __m128i zero = _mm_setzero_si128();
    int x = row.begin;
    for (; x + 4 <= row.end; x += 4) {
        const int* centre = row.centre_bytes + x;
        __m128i even_low = zero, even_high = zero, odd_low = zero, odd_high = zero;
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const std::uint8_t* tap = row.taps[t];
            const __m128i packed = _mm_setr_epi32(load32(tap + centre[0]), load32(tap + centre[1]),
                                                  load32(tap + centre[2]), load32(tap + centre[3]));
            const __m128i low = _mm_unpacklo_epi8(packed, zero);
            const __m128i high = _mm_unpackhi_epi8(packed, zero);
            if (((row.odd_taps >> t) & 1U) != 0) {
                odd_low = _mm_add_epi16(odd_low, low);
                odd_high = _mm_add_epi16(odd_high, high);
            } else {
                even_low = _mm_add_epi16(even_low, low);
                even_high = _mm_add_epi16(even_high, high);
            }
        }
        alignas(16) std::uint16_t even[16];
        alignas(16) std::uint16_t odd[16];
        _mm_store_si128(reinterpret_cast<__m128i*>(even), even_low);
        _mm_store_si128(reinterpret_cast<__m128i*>(even + 8), even_high);
        _mm_store_si128(reinterpret_cast<__m128i*>(odd), odd_low);
        _mm_store_si128(reinterpret_cast<__m128i*>(odd + 8), odd_high);
        for (int k = 0; k < 4; ++k) {
            const int lane = 4 * k;  // Y0 U Y1 V of pixel k
            store_yuv(row.out, x + k, even[lane] + odd[lane + 2], even[lane + 1] + odd[lane + 1],
                      even[lane + 3] + odd[lane + 3]);
        }
    }
    return x;
}

// Eight working pixels a step, each tap's eight 32-bit groups in one gather. 128-bit lane 0
// of `low` holds pixels 0-1, lane 1 pixels 4-5; `high` holds 2-3 and 6-7.
__attribute__((target("avx2"))) int filter_bgr_avx2(const FilterRow& row) noexcept {
    const __m256i zero = _mm256_setzero_si256();
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
    int x = row.begin;
    // The second 16-byte colour store spills 4 bytes into columns x + 8 and x + 9.
    for (; x + 8 <= row.end && x + 10 <= row.width; x += 8) {
        const __m256i index =
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row.centre_bytes + x));
        __m256i low = zero;
        __m256i high = zero;
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const __m256i packed =
                _mm256_i32gather_epi32(reinterpret_cast<const int*>(row.taps[t]), index, 1);
            low = _mm256_add_epi16(low, _mm256_unpacklo_epi8(packed, zero));
            high = _mm256_add_epi16(high, _mm256_unpackhi_epi8(packed, zero));
        }
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
        const __m256i planes = _mm256_permutevar8x32_epi32(
            _mm256_shuffle_epi8(pixels, to_planes), _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7));
        store64(row.out.blue + x, _mm256_extract_epi64(planes, 0));
        store64(row.out.green + x, _mm256_extract_epi64(planes, 1));
        store64(row.out.red + x, _mm256_extract_epi64(planes, 2));
    }
    return x;
}

// Tap sums [Y U ? V] (16-bit) to [Y - 16, U - 128, 1, V - 128] of their means, the terms of
// store_yuv()'s BT.601 sums (the 1 carries the rounding constant).
__attribute__((target("avx2"))) __m256i yuv_terms(__m256i sums) noexcept {
    const __m256i means = _mm256_srli_epi16(
        _mm256_add_epi16(sums, _mm256_set1_epi16(poisson_disk_tap_count / 2)), tap_shift);
    const __m256i offsets =
        _mm256_setr_epi16(16, 128, 0, 128, 16, 128, 0, 128, 16, 128, 0, 128, 16, 128, 0, 128);
    const __m256i one = _mm256_setr_epi16(0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0);
    return _mm256_blend_epi16(_mm256_sub_epi16(means, offsets), one, 0x44);
}

// Eight pixels, per 128-bit lane B0-3 G0-3 R0-3 (lane 1: pixels 4-7), to the planes, the
// interleaved row and grey. The second colour store spills 4 bytes into columns x + 8, x + 9.
__attribute__((target("avx2"))) void store_planar_eight(const FilterRow& row, int x,
                                                        __m256i planar) noexcept {
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

__attribute__((target("avx2"))) int filter_yuyv_avx2(const FilterRow& row) noexcept {
    const __m256i zero = _mm256_setzero_si256();
    // store_yuv()'s BT.601 weights for [Y - 16, U - 128, 1, V - 128], 128 the rounding.
    const __m256i to_blue =
        _mm256_setr_epi16(298, 516, 128, 0, 298, 516, 128, 0, 298, 516, 128, 0, 298, 516, 128, 0);
    const __m256i to_green = _mm256_setr_epi16(298, -100, 128, -208, 298, -100, 128, -208, 298,
                                               -100, 128, -208, 298, -100, 128, -208);
    const __m256i to_red =
        _mm256_setr_epi16(298, 0, 128, 409, 298, 0, 128, 409, 298, 0, 128, 409, 298, 0, 128, 409);
    int x = row.begin;
    for (; x + 8 <= row.end && x + 10 <= row.width; x += 8) {
        const __m256i index =
            _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row.centre_bytes + x));
        __m256i even_low = zero, even_high = zero, odd_low = zero, odd_high = zero;
        for (int t = 0; t < poisson_disk_tap_count; ++t) {
            const __m256i packed =
                _mm256_i32gather_epi32(reinterpret_cast<const int*>(row.taps[t]), index, 1);
            const __m256i low = _mm256_unpacklo_epi8(packed, zero);
            const __m256i high = _mm256_unpackhi_epi8(packed, zero);
            if (((row.odd_taps >> t) & 1U) != 0) {
                odd_low = _mm256_add_epi16(odd_low, low);
                odd_high = _mm256_add_epi16(odd_high, high);
            } else {
                even_low = _mm256_add_epi16(even_low, low);
                even_high = _mm256_add_epi16(even_high, high);
            }
        }
        // Per pixel (64 bits): Y from the even taps' first and the odd taps' second place, U
        // and V from both; the means, less the offsets, with a constant 1 in the spare lane.
        const __m256i both = _mm256_add_epi16(even_low, odd_low);
        const __m256i both_high = _mm256_add_epi16(even_high, odd_high);
        const __m256i luma_low = _mm256_add_epi16(even_low, _mm256_srli_epi64(odd_low, 32));
        const __m256i luma_high = _mm256_add_epi16(even_high, _mm256_srli_epi64(odd_high, 32));
        const __m256i low = yuv_terms(_mm256_blend_epi16(both, luma_low, 0x11));
        const __m256i high = yuv_terms(_mm256_blend_epi16(both_high, luma_high, 0x11));
        // B, G, R of pixels 0-3 in 128-bit lane 0 and 4-7 in lane 1, each term pair summed.
        const __m256i blue = _mm256_srai_epi32(
            _mm256_hadd_epi32(_mm256_madd_epi16(low, to_blue), _mm256_madd_epi16(high, to_blue)),
            8);
        const __m256i green = _mm256_srai_epi32(
            _mm256_hadd_epi32(_mm256_madd_epi16(low, to_green), _mm256_madd_epi16(high, to_green)),
            8);
        const __m256i red = _mm256_srai_epi32(
            _mm256_hadd_epi32(_mm256_madd_epi16(low, to_red), _mm256_madd_epi16(high, to_red)), 8);
        // Saturating packs clamp to 0..255: per lane B0-3 G0-3 R0-3 R0-3.
        const __m256i planar =
            _mm256_packus_epi16(_mm256_packus_epi32(blue, green), _mm256_packus_epi32(red, red));
        store_planar_eight(row, x, planar);
    }
    return x;
}

#else

int filter_bgr_sse2(const FilterRow& row) noexcept {
    return row.begin;
}
int filter_yuyv_sse2(const FilterRow& row) noexcept {
    return row.begin;
}
int filter_bgr_avx2(const FilterRow& row) noexcept {
    return row.begin;
}
int filter_yuyv_avx2(const FilterRow& row) noexcept {
    return row.begin;
}

#endif

}  // namespace detail
}  // namespace raypoint::core
