// SPDX-License-Identifier: MIT
// The Sobel edge image of preprocessing (paper 4.1).

#include "raypoint/core/edge_stage.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {
namespace {

// Squared Sobel gradients of one row of one plane; the border columns repeat their neighbour.
// Contiguous and restrict-qualified, so the compiler vectorizes it; always inlined into a
// plain and an AVX2 copy (edge_kernels below).
[[gnu::always_inline]] inline void squared_gradients(const std::uint8_t* __restrict above,
                                                     const std::uint8_t* __restrict here,
                                                     const std::uint8_t* __restrict below,
                                                     int* __restrict out, int width) noexcept {
    const auto gradient = [&](int i, int left, int right) {
        const int gx = (above[right] + 2 * here[right] + below[right]) -
                       (above[left] + 2 * here[left] + below[left]);
        const int gy = (below[left] + 2 * below[i] + below[right]) -
                       (above[left] + 2 * above[i] + above[right]);
        return gx * gx + gy * gy;
    };
    out[0] = gradient(0, 0, 1);
    out[width - 1] = gradient(width - 1, width - 2, width - 1);
    for (int i = 1; i < width - 1; ++i) {
        const int gx = (above[i + 1] + 2 * here[i + 1] + below[i + 1]) -
                       (above[i - 1] + 2 * here[i - 1] + below[i - 1]);
        const int gy = (below[i - 1] + 2 * below[i] + below[i + 1]) -
                       (above[i - 1] + 2 * above[i] + above[i + 1]);
        out[i] = gx * gx + gy * gy;
    }
}

// The strongest plane's gradient to the 8-bit magnitude (L2 norm, saturated) and the edge
// image (the magnitude over the threshold, 0 elsewhere).
[[gnu::always_inline]] inline void magnitudes(const int* __restrict first,
                                              const int* __restrict second,
                                              const int* __restrict third,
                                              std::uint8_t* __restrict magnitude,
                                              std::uint8_t* __restrict edge, int width,
                                              int threshold) noexcept {
    for (int x = 0; x < width; ++x) {
        const int strongest = std::max(first[x], std::max(second[x], third[x]));
        const int value =
            static_cast<int>(std::min(255.0F, std::sqrt(static_cast<float>(strongest))));
        magnitude[x] = static_cast<std::uint8_t>(value);
        // Edge pixels keep their magnitude: the raster estimator climbs it to the ridge.
        edge[x] = value > threshold ? static_cast<std::uint8_t>(value) : 0;
    }
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
