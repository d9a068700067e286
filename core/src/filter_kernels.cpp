// SPDX-License-Identifier: MIT
// SSE2 kernels of the Poisson-disk filter's interior (AVX2: filter_kernels_avx2.cpp). SSE2 is
// part of x86-64. They store exactly what store_bgr() / store_yuv() would.

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
    const std::uint8_t* fetch = row.fetch;
    int x = row.begin;
    for (; x + 4 <= row.end && x + 4 < row.width; x += 4) {
        fetch = prefetch_lines(row, fetch, row.fetch_lines);
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
    prefetch_lines(row, fetch, all_lines);
    return x;
}

// Centres of one parity: a tap's Y is the first or the second of its pair for every working
// pixel alike, so whole Y0 U Y1 V groups are summed split by the tap's parity, the Y picked at the
// end.
int filter_yuyv_sse2(const FilterRow& row) noexcept {
    const __m128i zero = _mm_setzero_si128();
    const std::uint8_t* fetch = row.fetch;
    int x = row.begin;
    for (; x + 4 <= row.end; x += 4) {
        fetch = prefetch_lines(row, fetch, row.fetch_lines);
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
    prefetch_lines(row, fetch, all_lines);
    return x;
}

#else

int filter_bgr_sse2(const FilterRow& row) noexcept {
    return row.begin;
}
int filter_yuyv_sse2(const FilterRow& row) noexcept {
    return row.begin;
}

#endif

}  // namespace detail
}  // namespace raypoint::core
