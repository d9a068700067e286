// The Poisson-disk filter and subsampling of preprocessing (paper 4.1), for BGR and YUYV input.

#include <algorithm>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {
namespace {

std::uint8_t clamp_byte(int value) noexcept {
    return static_cast<std::uint8_t>(std::clamp(value, 0, 255));
}

}  // namespace

// The filter is evaluated only at the working pixels' centres: filtering the whole frame and
// then subsampling gives the same values at 16x the cost for 640x480. Working pixel outside,
// taps inside, so the sums stay in registers; the interior skips the clamped column tables.
void Preprocessor::filter_bgr(const FrameView& frame) noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    cv::Mat& out = color_[current_];
    for (int y = 0; y < settings_.work_height; ++y) {
        start_row(frame, y);
        auto* target = out.ptr<std::uint8_t>(y);
        const auto store = [&](int x, unsigned b, unsigned g, unsigned r) {
            target[x * 3 + 0] = static_cast<std::uint8_t>((b + tap_count / 2) / tap_count);
            target[x * 3 + 1] = static_cast<std::uint8_t>((g + tap_count / 2) / tap_count);
            target[x * 3 + 2] = static_cast<std::uint8_t>((r + tap_count / 2) / tap_count);
        };
        const auto clamped = [&](int x) {
            unsigned b = 0, g = 0, r = 0;
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + tap_columns_[t][x] * 3;
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            store(x, b, g, r);
        };
        int x = 0;
        for (; x < interior_begin_; ++x)
            clamped(x);
#if defined(__SSE2__)
        // Four working pixels a step: each tap's B, G, R (and the next pixel's B, ignored) are
        // one 32-bit load widened to 16-bit lanes; 16 taps x 255 fit in 16 bits. The interior
        // has a column to spare on the right, so the 4th byte is inside the frame.
        for (unsigned t = 0; t < tap_count; ++t)
            tap_row_pointers_[t] += tap_dx_[t] * 3;
        const __m128i zero = _mm_setzero_si128();
        for (; x + 4 <= interior_end_; x += 4) {
            const int c0 = centre_columns_[x] * 3;
            const int c1 = centre_columns_[x + 1] * 3;
            const int c2 = centre_columns_[x + 2] * 3;
            const int c3 = centre_columns_[x + 3] * 3;
            __m128i low = _mm_setzero_si128();   // pixels x, x+1
            __m128i high = _mm_setzero_si128();  // pixels x+2, x+3
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* row = tap_row_pointers_[t];
                std::uint32_t p0 = 0, p1 = 0, p2 = 0, p3 = 0;
                std::memcpy(&p0, row + c0, 4);
                std::memcpy(&p1, row + c1, 4);
                std::memcpy(&p2, row + c2, 4);
                std::memcpy(&p3, row + c3, 4);
                const __m128i packed = _mm_setr_epi32(static_cast<int>(p0), static_cast<int>(p1),
                                                      static_cast<int>(p2), static_cast<int>(p3));
                low = _mm_add_epi16(low, _mm_unpacklo_epi8(packed, zero));
                high = _mm_add_epi16(high, _mm_unpackhi_epi8(packed, zero));
            }
            alignas(16) std::uint16_t lanes[16];
            _mm_store_si128(reinterpret_cast<__m128i*>(lanes), low);
            _mm_store_si128(reinterpret_cast<__m128i*>(lanes + 8), high);
            for (int k = 0; k < 4; ++k)
                store(x + k, lanes[4 * k], lanes[4 * k + 1], lanes[4 * k + 2]);
        }
        for (unsigned t = 0; t < tap_count; ++t)
            tap_row_pointers_[t] -= tap_dx_[t] * 3;
#endif
        for (; x < interior_end_; ++x) {
            const int centre = centre_columns_[x];
            unsigned b = 0, g = 0, r = 0;
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + (centre + tap_dx_[t]) * 3;
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            store(x, b, g, r);
        }
        for (x = std::max(interior_end_, interior_begin_); x < settings_.work_width; ++x) {
            clamped(x);
        }
    }
}

// Points each tap at its input row for working row y, and fetches the rows of the next.
void Preprocessor::start_row(const FrameView& frame, int y) noexcept {
    for (std::size_t t = 0; t < tap_row_pointers_.size(); ++t) {
        tap_row_pointers_[t] =
            frame.data + static_cast<std::ptrdiff_t>(tap_rows_[t][y]) * frame.stride;
    }
    prefetch_rows(frame, y + 1);
}

// A camera frame arrives cold in memory; the taps read 16 rows at a time, too many streams
// for the hardware prefetcher, so the rows the next working row adds are fetched ahead.
void Preprocessor::prefetch_rows(const FrameView& frame, int next_y) const noexcept {
#if defined(__SSE2__)
    if (next_y >= settings_.work_height) return;
    const int first = last_tap_row_[next_y - 1] + 1;
    const int last = last_tap_row_[next_y];
    const int bytes = frame.width * (frame.format == PixelFormat::bgr ? 3 : 2);
    for (int row = first; row <= last; ++row) {
        const std::uint8_t* start = frame.data + static_cast<std::ptrdiff_t>(row) * frame.stride;
        for (int offset = 0; offset < bytes; offset += 64) {
            _mm_prefetch(reinterpret_cast<const char*>(start + offset), _MM_HINT_T0);
        }
    }
#else
    (void)frame;
    (void)next_y;
#endif
}

// One working pixel of a YUYV frame through the clamped column tables (borders, odd scales).
template <typename Store>
void Preprocessor::store_yuyv_clamped(int x, Store& store) const noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    const bool interior = x >= interior_begin_ && x < interior_end_;
    unsigned sum_y = 0, sum_u = 0, sum_v = 0;
    for (unsigned t = 0; t < tap_count; ++t) {
        const int column = interior ? centre_columns_[x] + tap_dx_[t] : tap_columns_[t][x];
        const std::uint8_t* pair = tap_row_pointers_[t] + (column & ~1) * 2;
        sum_y += pair[(column & 1) * 2];
        sum_u += pair[1];
        sum_v += pair[3];
    }
    store(x, sum_y, sum_u, sum_v);
}

// YUYV: Y from the pixel itself, U and V from its pair; averaged as YUV, then converted to BGR
// with BT.601 limited range, the usual meaning of V4L2_PIX_FMT_YUYV from webcams.
void Preprocessor::filter_yuyv(const FrameView& frame) noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    cv::Mat& out = color_[current_];
    for (int y = 0; y < settings_.work_height; ++y) {
        start_row(frame, y);
        auto* target = out.ptr<std::uint8_t>(y);
        const auto store = [&](int x, unsigned sum_y, unsigned sum_u, unsigned sum_v) {
            const int luma = static_cast<int>((sum_y + tap_count / 2) / tap_count) - 16;
            const int u = static_cast<int>((sum_u + tap_count / 2) / tap_count) - 128;
            const int v = static_cast<int>((sum_v + tap_count / 2) / tap_count) - 128;
            const int scaled = 298 * luma + 128;
            target[x * 3 + 0] = clamp_byte((scaled + 516 * u) >> 8);
            target[x * 3 + 1] = clamp_byte((scaled - 100 * u - 208 * v) >> 8);
            target[x * 3 + 2] = clamp_byte((scaled + 409 * v) >> 8);
        };
        int x = 0;
#if defined(__SSE2__)
        // With an even centre parity (integer scales: 640, 1280, 1920 wide to 160) a tap's Y is
        // the first or the second of its pair for every working pixel alike, so four pixels a
        // step sum whole Y0 U Y1 V groups, split by the tap's parity, and pick the Y at the end.
        if (uniform_parity_) {
            for (; x < interior_begin_; ++x)
                store_yuyv_clamped(x, store);
            const __m128i zero = _mm_setzero_si128();
            for (; x + 4 <= interior_end_; x += 4) {
                __m128i even_low = zero, even_high = zero, odd_low = zero, odd_high = zero;
                for (unsigned t = 0; t < tap_count; ++t) {
                    const std::uint8_t* row = tap_row_pointers_[t];
                    std::uint32_t p[4];
                    for (int k = 0; k < 4; ++k) {
                        std::memcpy(&p[k], row + ((centre_columns_[x + k] + tap_dx_[t]) & ~1) * 2,
                                    4);
                    }
                    const __m128i packed =
                        _mm_setr_epi32(static_cast<int>(p[0]), static_cast<int>(p[1]),
                                       static_cast<int>(p[2]), static_cast<int>(p[3]));
                    const __m128i low = _mm_unpacklo_epi8(packed, zero);
                    const __m128i high = _mm_unpackhi_epi8(packed, zero);
                    if (tap_odd_[t] != 0) {
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
                    store(x + k, even[lane] + odd[lane + 2], even[lane + 1] + odd[lane + 1],
                          even[lane + 3] + odd[lane + 3]);
                }
            }
        }
#endif
        for (; x < settings_.work_width; ++x)
            store_yuyv_clamped(x, store);
    }
}

}  // namespace raypoint::core
