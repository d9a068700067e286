// SPDX-License-Identifier: MIT
// The Sobel edge image of preprocessing (paper 4.1).

#include "raypoint/core/edge_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace raypoint::core {
namespace {

// The squared Sobel gradient at column i of one plane, its neighbours at columns left and
// right (the border columns repeat their neighbour: left or right is i there).
inline int squared_gradient(const std::uint8_t* above, const std::uint8_t* here,
                            const std::uint8_t* below, int i, int left, int right) noexcept {
    const int gx = (above[right] + 2 * here[right] + below[right]) -
                   (above[left] + 2 * here[left] + below[left]);
    const int gy =
        (below[left] + 2 * below[i] + below[right]) - (above[left] + 2 * above[i] + above[right]);
    return gx * gx + gy * gy;
}

// Squared Sobel gradients of one row of one plane; the border columns repeat their neighbour.
// Contiguous and restrict-qualified, so the compiler vectorizes it; always inlined into a
// plain and an AVX2 copy (edge_kernels below).
[[gnu::always_inline]] inline void squared_gradients(const std::uint8_t* __restrict above,
                                                     const std::uint8_t* __restrict here,
                                                     const std::uint8_t* __restrict below,
                                                     int* __restrict out, int width) noexcept {
    out[0] = squared_gradient(above, here, below, 0, 0, 1);
    out[width - 1] = squared_gradient(above, here, below, width - 1, width - 2, width - 1);
    for (int i = 1; i < width - 1; ++i) {
        const int gx = (above[i + 1] + 2 * here[i + 1] + below[i + 1]) -
                       (above[i - 1] + 2 * here[i - 1] + below[i - 1]);
        const int gy = (below[i - 1] + 2 * below[i] + below[i + 1]) -
                       (above[i - 1] + 2 * above[i] + above[i + 1]);
        out[i] = gx * gx + gy * gy;
    }
}

// The strongest plane's squared gradient to the 8-bit magnitude (L2 norm, saturated) and the
// edge image (the magnitude over the threshold, 0 elsewhere).
[[gnu::always_inline]] inline void store_magnitude(int strongest, std::uint8_t* magnitude,
                                                   std::uint8_t* edge, int threshold) noexcept {
    const int value = static_cast<int>(std::min(255.0F, std::sqrt(static_cast<float>(strongest))));
    *magnitude = static_cast<std::uint8_t>(value);
    // Edge pixels keep their magnitude: the raster estimator climbs it to the ridge.
    *edge = value > threshold ? static_cast<std::uint8_t>(value) : 0;
}

// The strongest plane's gradient to the 8-bit magnitude (L2 norm, saturated) and the edge
// image (the magnitude over the threshold, 0 elsewhere).
[[gnu::always_inline]] inline void magnitudes(const int* __restrict first,
                                              const int* __restrict second,
                                              const int* __restrict third,
                                              std::uint8_t* __restrict magnitude,
                                              std::uint8_t* __restrict edge, int width,
                                              int threshold) noexcept {
    for (int x = 0; x < width; ++x)
        store_magnitude(std::max(first[x], std::max(second[x], third[x])), magnitude + x, edge + x,
                        threshold);
}

struct EdgeKernels {
    void (*gradients)(const std::uint8_t*, const std::uint8_t*, const std::uint8_t*, int*,
                      int) noexcept;
    void (*magnitudes)(const int*, const int*, const int*, std::uint8_t*, std::uint8_t*, int,
                       int) noexcept;
};

void gradients_plain(const std::uint8_t* above, const std::uint8_t* here, const std::uint8_t* below,
                     int* out, int width) noexcept {
    squared_gradients(above, here, below, out, width);
}
void magnitudes_plain(const int* first, const int* second, const int* third,
                      std::uint8_t* magnitude, std::uint8_t* edge, int width,
                      int threshold) noexcept {
    magnitudes(first, second, third, magnitude, edge, width, threshold);
}
#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] void gradients_avx2(const std::uint8_t* above, const std::uint8_t* here,
                                            const std::uint8_t* below, int* out,
                                            int width) noexcept {
    squared_gradients(above, here, below, out, width);
}
[[gnu::target("avx2")]] void magnitudes_avx2(const int* first, const int* second, const int* third,
                                             std::uint8_t* magnitude, std::uint8_t* edge, int width,
                                             int threshold) noexcept {
    magnitudes(first, second, third, magnitude, edge, width, threshold);
}
#endif

// One plane's rows around the row being computed (the border rows repeat theirs).
struct PlaneRows {
    const std::uint8_t* above;
    const std::uint8_t* here;
    const std::uint8_t* below;
};

#if defined(__x86_64__) && defined(__GNUC__)
#define RAYPOINT_AVX2 __attribute__((target("avx2")))
RAYPOINT_AVX2 inline __m256i widen(const std::uint8_t* at) noexcept {
    return _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(at)));
}

// store_magnitude()'s value, eight at a time: IEEE square root, capped at 255, truncated.
RAYPOINT_AVX2 inline __m256i magnitude_values(__m256i squared, __m256i limit) noexcept {
    const __m256 root = _mm256_sqrt_ps(_mm256_cvtepi32_ps(squared));
    return _mm256_cvttps_epi32(_mm256_min_ps(root, _mm256_castsi256_ps(limit)));
}

// Pixels 0-3 and 8-11 in `low`, 4-7 and 12-15 in `high` (32-bit lanes, 0..255): the packs put
// them back in order, then 8 bytes from each 128-bit lane.
RAYPOINT_AVX2 inline void store_sixteen(std::uint8_t* at, __m256i low, __m256i high) noexcept {
    const __m256i words = _mm256_packus_epi32(low, high);
    const __m256i bytes = _mm256_permute4x64_epi64(_mm256_packus_epi16(words, words), 0x08);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at), _mm256_castsi256_si128(bytes));
}

// A whole row of the magnitude and edge images, every plane at once, 16 pixels a step in
// 16-bit lanes (a gradient is within +-1020), the squares summed in one vpmaddwd of the
// interleaved gx, gy (at most 2 x 1020^2, 32 bits). The same integers, and the same IEEE
// square root and truncation, as squared_gradients() and magnitudes(): the same bytes, with
// about half the instructions (no row of squares written out and read back). Needs width >= 18.
RAYPOINT_AVX2 void edge_row_avx2(const PlaneRows* planes, int plane_count, std::uint8_t* magnitude,
                                 std::uint8_t* edge, int width, int threshold) noexcept {
    const auto border = [&](int i, int left, int right) {
        int strongest = 0;
        for (int c = 0; c < plane_count; ++c) {
            const PlaneRows& p = planes[c];
            strongest =
                std::max(strongest, squared_gradient(p.above, p.here, p.below, i, left, right));
        }
        store_magnitude(strongest, magnitude + i, edge + i, threshold);
    };
    border(0, 0, 1);
    border(width - 1, width - 2, width - 1);
    const __m256i limit = _mm256_castps_si256(_mm256_set1_ps(255.0F));
    const __m256i over = _mm256_set1_epi32(threshold);
    // Columns 1 .. width - 2; the last step ends at width - 2, computing again up to 15
    // columns the previous one did (the same values).
    for (int i = 1;; i += 16) {
        i = std::min(i, width - 17);
        __m256i strongest_low = _mm256_setzero_si256();   // pixels 0-3 and 8-11
        __m256i strongest_high = _mm256_setzero_si256();  // pixels 4-7 and 12-15
        for (int c = 0; c < plane_count; ++c) {
            const PlaneRows& p = planes[c];
            const __m256i above_left = widen(p.above + i - 1);
            const __m256i above_right = widen(p.above + i + 1);
            const __m256i below_left = widen(p.below + i - 1);
            const __m256i below_right = widen(p.below + i + 1);
            const __m256i here_left = widen(p.here + i - 1);
            const __m256i here_right = widen(p.here + i + 1);
            const __m256i gx =
                _mm256_sub_epi16(_mm256_add_epi16(_mm256_add_epi16(above_right, below_right),
                                                  _mm256_add_epi16(here_right, here_right)),
                                 _mm256_add_epi16(_mm256_add_epi16(above_left, below_left),
                                                  _mm256_add_epi16(here_left, here_left)));
            const __m256i down = _mm256_sub_epi16(widen(p.below + i), widen(p.above + i));
            const __m256i gy =
                _mm256_add_epi16(_mm256_add_epi16(_mm256_sub_epi16(below_left, above_left),
                                                  _mm256_sub_epi16(below_right, above_right)),
                                 _mm256_add_epi16(down, down));
            const __m256i low = _mm256_unpacklo_epi16(gx, gy);
            const __m256i high = _mm256_unpackhi_epi16(gx, gy);
            strongest_low = _mm256_max_epi32(strongest_low, _mm256_madd_epi16(low, low));
            strongest_high = _mm256_max_epi32(strongest_high, _mm256_madd_epi16(high, high));
        }
        const __m256i value_low = magnitude_values(strongest_low, limit);
        const __m256i value_high = magnitude_values(strongest_high, limit);
        store_sixteen(magnitude + i, value_low, value_high);
        store_sixteen(edge + i, _mm256_and_si256(value_low, _mm256_cmpgt_epi32(value_low, over)),
                      _mm256_and_si256(value_high, _mm256_cmpgt_epi32(value_high, over)));
        if (i == width - 17) break;
    }
}
#endif

EdgeKernels edge_kernels(InstructionSet instructions) noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
    if (instructions == InstructionSet::avx2) return {gradients_avx2, magnitudes_avx2};
#else
    (void)instructions;
#endif
    return {gradients_plain, magnitudes_plain};
}

}  // namespace

EdgeStage::EdgeStage(const PreprocessSettings& settings, InstructionSet instructions)
    : source_(settings.edge_source),
      threshold_(settings.edge_threshold),
      instructions_(instructions),
      squared_channels_(static_cast<std::size_t>(settings.work_width) * 3) {
    const cv::Size size(settings.work_width, settings.work_height);
    magnitude_.create(size, CV_8U);
    edges_.create(size, CV_8U);
    magnitude_.setTo(cv::Scalar::all(0));
    edges_.setTo(cv::Scalar::all(0));
}

// Sobel 3x3 on each plane, replicated border; the magnitude is the L2 norm, saturated to 8
// bits as in a grey edge image. EdgeSource::luma uses the grey image's gradient (paper 4.1);
// max_channel the strongest channel's, which keeps a skin hand's outline over a background of
// equal brightness. Written out rather than cv::Sobel, which allocates its filter every call.
// Planes (the filter writes B, G and R apart) keep every loop contiguous.
void EdgeStage::compute(const cv::Mat& grey, const cv::Mat& planes) noexcept {
    const int width = magnitude_.cols;
    const int height = magnitude_.rows;
    int plane_count = 1;
    const cv::Mat* source = &grey;
    switch (source_) {
        case EdgeSource::luma:
            break;
        case EdgeSource::max_channel:
            plane_count = 3;
            source = &planes;
            break;
    }
#if defined(__x86_64__) && defined(__GNUC__)
    if (instructions_ == InstructionSet::avx2 && width >= 18) {
        for (int y = 0; y < height; ++y) {
            std::array<PlaneRows, 3> rows{};
            for (int c = 0; c < plane_count; ++c) {
                const int first_row = c * height;
                rows[c] = {source->ptr<std::uint8_t>(first_row + std::max(y - 1, 0)),
                           source->ptr<std::uint8_t>(first_row + y),
                           source->ptr<std::uint8_t>(first_row + std::min(y + 1, height - 1))};
            }
            edge_row_avx2(rows.data(), plane_count, magnitude_.ptr<std::uint8_t>(y),
                          edges_.ptr<std::uint8_t>(y), width, threshold_);
        }
        return;
    }
#endif
    const EdgeKernels kernels = edge_kernels(instructions_);
    int* const squared = squared_channels_.data();
    for (int y = 0; y < height; ++y) {
        for (int c = 0; c < plane_count; ++c) {
            const int first_row = c * height;
            kernels.gradients(source->ptr<std::uint8_t>(first_row + std::max(y - 1, 0)),
                              source->ptr<std::uint8_t>(first_row + y),
                              source->ptr<std::uint8_t>(first_row + std::min(y + 1, height - 1)),
                              squared + c * width, width);
        }
        const int* last = squared + (plane_count - 1) * width;
        kernels.magnitudes(squared, plane_count == 3 ? squared + width : squared, last,
                           magnitude_.ptr<std::uint8_t>(y), edges_.ptr<std::uint8_t>(y), width,
                           threshold_);
    }
}

}  // namespace raypoint::core
