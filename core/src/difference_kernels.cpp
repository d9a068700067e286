// SPDX-License-Identifier: MIT
// The difference stage's kernels (difference_kernels.hpp): portable loops and their SSE2 form.

#include "difference_kernels.hpp"

#include <algorithm>

#if defined(__x86_64__) && defined(__GNUC__)
#include <emmintrin.h>
#endif

namespace raypoint::core::detail {
namespace {

// The paper's offset by minimum passes: the smallest value is the first distinct one, and each
// pass finds the smallest value above the last one found. A pass takes the minimum of
// (value - from) mod 256: the values from `from` on give value - from <= 255 - from, those
// below it give at least 256 - from, so the minimum is at most 255 - from exactly when a value
// from `from` on is present, and is then the nearest one's distance. `minima` passes at most
// (10 by default) over the working pixels replace a 256-bin histogram.
template <std::uint8_t (*smallest_from)(const std::uint8_t*, std::size_t, std::uint8_t)>
int distinct_offset_by(const std::uint8_t* values, std::size_t length, std::uint8_t smallest,
                       int minima) noexcept {
    if (length == 0 || minima <= 0) return 0;
    int largest = smallest;
    for (int distinct = 1; distinct < minima && largest < 255; ++distinct) {
        const int from = largest + 1;
        const int least = smallest_from(values, length, static_cast<std::uint8_t>(from));
        if (least > 255 - from) break;  // no value above `largest`
        largest = from + least;
    }
    return largest;
}

// One pass: the smallest (value - from) mod 256.
std::uint8_t scalar_smallest_from(const std::uint8_t* values, std::size_t length,
                                  std::uint8_t from) noexcept {
    std::uint8_t least = 255;
    for (std::size_t i = 0; i < length; ++i)
        least = std::min(least, static_cast<std::uint8_t>(values[i] - from));
    return least;
}

inline std::uint8_t absolute(std::uint8_t a, std::uint8_t b) noexcept {
    return static_cast<std::uint8_t>(std::max(a, b) - std::min(a, b));
}

}  // namespace

namespace portable {

std::uint8_t absolute_difference(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                                 int length, std::uint8_t smallest) noexcept {
    for (int i = 0; i < length; ++i) {
        out[i] = absolute(a[i], b[i]);
        smallest = std::min(smallest, out[i]);
    }
    return smallest;
}

std::uint8_t strongest_channel(const std::uint8_t* color, const std::uint8_t* previous,
                               std::uint8_t* out, int pixels, std::uint8_t smallest) noexcept {
    for (int x = 0; x < pixels; ++x) {
        const std::uint8_t* now = color + 3 * x;
        const std::uint8_t* before = previous + 3 * x;
        out[x] = std::max({absolute(now[0], before[0]), absolute(now[1], before[1]),
                           absolute(now[2], before[2])});
        smallest = std::min(smallest, out[x]);
    }
    return smallest;
}

int distinct_offset(const std::uint8_t* values, std::size_t length, std::uint8_t smallest,
                    int minima) noexcept {
    return distinct_offset_by<scalar_smallest_from>(values, length, smallest, minima);
}

std::int64_t compensate(std::uint8_t* values, std::size_t length, std::uint8_t offset) noexcept {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < length; ++i) {
        values[i] = static_cast<std::uint8_t>(values[i] > offset ? values[i] - offset : 0);
        sum += values[i];
    }
    return sum;
}

std::int64_t compensated_sum(const std::uint8_t* values, std::size_t length,
                             std::uint8_t offset) noexcept {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < length; ++i)
        sum += values[i] > offset ? values[i] - offset : 0;
    return sum;
}

}  // namespace portable

#if defined(__x86_64__) && defined(__GNUC__)
namespace sse2 {
namespace {

inline __m128i load(const std::uint8_t* at) noexcept {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
}

inline void store(std::uint8_t* at, __m128i value) noexcept {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at), value);
}

inline __m128i absolute(__m128i a, __m128i b) noexcept {
    return _mm_or_si128(_mm_subs_epu8(a, b), _mm_subs_epu8(b, a));
}

inline std::uint8_t horizontal_min(__m128i v) noexcept {
    v = _mm_min_epu8(v, _mm_srli_si128(v, 8));
    v = _mm_min_epu8(v, _mm_srli_si128(v, 4));
    v = _mm_min_epu8(v, _mm_srli_si128(v, 2));
    v = _mm_min_epu8(v, _mm_srli_si128(v, 1));
    return static_cast<std::uint8_t>(_mm_cvtsi128_si32(v));
}

inline std::int64_t horizontal_sum(__m128i two) noexcept {
    return _mm_cvtsi128_si64(two) + _mm_cvtsi128_si64(_mm_unpackhi_epi64(two, two));
}

// A pass stops at the first block holding `from` itself (a minimum of 0: none can be smaller):
// the values just above the smallest are usually many (noise), so most passes read a block or
// two. A minimum takes each value any number of times: the last values are read again rather
// than one by one.
std::uint8_t smallest_from(const std::uint8_t* values, std::size_t length,
                           std::uint8_t from) noexcept {
    if (length < 16) return scalar_smallest_from(values, length, from);
    const __m128i shift = _mm_set1_epi8(static_cast<char>(from));
    const __m128i zero = _mm_setzero_si128();
    const auto shifted = [&shift, values](std::size_t at) noexcept {
        return _mm_sub_epi8(load(values + at), shift);
    };
    __m128i least = _mm_set1_epi8(-1);
    std::size_t i = 0;
    for (; i + 128 <= length; i += 128) {
        const __m128i block =
            _mm_min_epu8(_mm_min_epu8(_mm_min_epu8(shifted(i), shifted(i + 16)),
                                      _mm_min_epu8(shifted(i + 32), shifted(i + 48))),
                         _mm_min_epu8(_mm_min_epu8(shifted(i + 64), shifted(i + 80)),
                                      _mm_min_epu8(shifted(i + 96), shifted(i + 112))));
        if (_mm_movemask_epi8(_mm_cmpeq_epi8(block, zero)) != 0) return 0;
        least = _mm_min_epu8(least, block);
    }
    for (; i + 16 <= length; i += 16)
        least = _mm_min_epu8(least, shifted(i));
    if (i < length) least = _mm_min_epu8(least, shifted(length - 16));
    return horizontal_min(least);
}

}  // namespace

std::uint8_t absolute_difference(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                                 int length, std::uint8_t smallest) noexcept {
    if (length < 16) return portable::absolute_difference(a, b, out, length, smallest);
    __m128i least = _mm_set1_epi8(static_cast<char>(smallest));
    int i = 0;
    for (; i + 16 <= length; i += 16) {
        const __m128i difference = absolute(load(a + i), load(b + i));
        store(out + i, difference);
        least = _mm_min_epu8(least, difference);
    }
    if (i < length) {  // the last 16 again: the same bytes, and a minimum takes them twice
        const __m128i difference = absolute(load(a + length - 16), load(b + length - 16));
        store(out + length - 16, difference);
        least = _mm_min_epu8(least, difference);
    }
    return horizontal_min(least);
}

// 16 pixels from 48 bytes: the channel differences d0 d1 d2 (a stream of 48 bytes, pixel p at
// 3p), then at every byte i of each the largest of stream bytes i, i + 1, i + 2 (shifted in from
// the next 16 bytes). A pixel starts at every third byte, and the three vectors' starts fall on
// the three residues: d0's at i = 0 mod 3 (pixels 0 to 5), d1's at 2 mod 3 (6 to 10), d2's at
// 1 mod 3 (11 to 15), so one mask per vector gathers the 16 maxima without a shuffle.
std::uint8_t strongest_channel(const std::uint8_t* color, const std::uint8_t* previous,
                               std::uint8_t* out, int pixels, std::uint8_t smallest) noexcept {
    const __m128i from_d0 = _mm_setr_epi8(-1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1);
    const __m128i from_d2 = _mm_setr_epi8(0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0);
    const __m128i from_d1 = _mm_setr_epi8(0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0);
    __m128i least = _mm_set1_epi8(static_cast<char>(smallest));
    int x = 0;
    for (; x + 16 <= pixels; x += 16) {
        const std::uint8_t* now = color + 3 * x;
        const std::uint8_t* before = previous + 3 * x;
        const __m128i d0 = absolute(load(now), load(before));
        const __m128i d1 = absolute(load(now + 16), load(before + 16));
        const __m128i d2 = absolute(load(now + 32), load(before + 32));
        const __m128i m0 = _mm_max_epu8(
            d0, _mm_max_epu8(_mm_or_si128(_mm_srli_si128(d0, 1), _mm_slli_si128(d1, 15)),
                             _mm_or_si128(_mm_srli_si128(d0, 2), _mm_slli_si128(d1, 14))));
        const __m128i m1 = _mm_max_epu8(
            d1, _mm_max_epu8(_mm_or_si128(_mm_srli_si128(d1, 1), _mm_slli_si128(d2, 15)),
                             _mm_or_si128(_mm_srli_si128(d1, 2), _mm_slli_si128(d2, 14))));
        const __m128i m2 =
            _mm_max_epu8(d2, _mm_max_epu8(_mm_srli_si128(d2, 1), _mm_srli_si128(d2, 2)));
        const __m128i strongest =
            _mm_or_si128(_mm_or_si128(_mm_and_si128(m0, from_d0), _mm_and_si128(m1, from_d1)),
                         _mm_and_si128(m2, from_d2));
        store(out + x, strongest);
        least = _mm_min_epu8(least, strongest);
    }
    return portable::strongest_channel(color + 3 * x, previous + 3 * x, out + x, pixels - x,
                                       horizontal_min(least));
}

int distinct_offset(const std::uint8_t* values, std::size_t length, std::uint8_t smallest,
                    int minima) noexcept {
    return distinct_offset_by<smallest_from>(values, length, smallest, minima);
}

namespace {
// max(0, value - offset) is the saturating subtraction, and psadbw against 0 sums 8 bytes
// into a 64-bit lane: exact. `out` (values itself, or nothing) receives the results.
template <bool stored>
std::int64_t compensated_by(const std::uint8_t* values, std::uint8_t* out, std::size_t length,
                            std::uint8_t offset) noexcept {
    const __m128i subtrahend = _mm_set1_epi8(static_cast<char>(offset));
    const __m128i zero = _mm_setzero_si128();
    __m128i sum0 = zero;
    __m128i sum1 = zero;
    std::size_t i = 0;
    for (; i + 32 <= length; i += 32) {
        const __m128i compensated0 = _mm_subs_epu8(load(values + i), subtrahend);
        const __m128i compensated1 = _mm_subs_epu8(load(values + i + 16), subtrahend);
        if constexpr (stored) {
            store(out + i, compensated0);
            store(out + i + 16, compensated1);
        }
        sum0 = _mm_add_epi64(sum0, _mm_sad_epu8(compensated0, zero));
        sum1 = _mm_add_epi64(sum1, _mm_sad_epu8(compensated1, zero));
    }
    const std::int64_t rest = stored ? portable::compensate(out + i, length - i, offset)
                                     : portable::compensated_sum(values + i, length - i, offset);
    return horizontal_sum(_mm_add_epi64(sum0, sum1)) + rest;
}
}  // namespace

std::int64_t compensate(std::uint8_t* values, std::size_t length, std::uint8_t offset) noexcept {
    return compensated_by<true>(values, values, length, offset);
}

std::int64_t compensated_sum(const std::uint8_t* values, std::size_t length,
                             std::uint8_t offset) noexcept {
    return compensated_by<false>(values, nullptr, length, offset);
}

}  // namespace sse2
#endif

}  // namespace raypoint::core::detail
