// The Sobel edge image of preprocessing (paper 4.1).

#include <algorithm>
#include <cmath>

#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {

// Sobel 3x3 on each channel, replicated border; the magnitude is the L2 norm, saturated to 8
// bits as in a grey edge image. EdgeSource::luma uses the grey image's gradient (paper 4.1);
// max_channel the strongest channel's, which keeps a skin hand's outline over a background of
// equal brightness. Written out rather than cv::Sobel, which allocates its filter every call.
void Preprocessor::compute_edges() noexcept {
    switch (settings_.edge_source) {
        case EdgeSource::luma:
            compute_edges_of<1>(gray_[current_]);
            break;
        case EdgeSource::max_channel:
            compute_edges_of<3>(color_[current_]);
            break;
    }
}

// Squared gradients of one row's samples, all channels interleaved; the border columns repeat
// their neighbour. Restrict-qualified and with the channel stride a constant, so the compiler
// vectorizes it.
template <int Channels>
static void squared_gradients(const std::uint8_t* __restrict above,
                              const std::uint8_t* __restrict here,
                              const std::uint8_t* __restrict below, int* __restrict out,
                              int row_length) noexcept {
    const auto gradient = [&](int i, int left, int right) {
        const int gx = (above[right] + 2 * here[right] + below[right]) -
                       (above[left] + 2 * here[left] + below[left]);
        const int gy = (below[left] + 2 * below[i] + below[right]) -
                       (above[left] + 2 * above[i] + above[right]);
        return gx * gx + gy * gy;
    };
    for (int i = 0; i < Channels; ++i) {
        out[i] = gradient(i, i, i + Channels);
        const int last = row_length - Channels + i;
        out[last] = gradient(last, last - Channels, last);
    }
    for (int i = Channels; i < row_length - Channels; ++i) {
        const int gx = (above[i + Channels] + 2 * here[i + Channels] + below[i + Channels]) -
                       (above[i - Channels] + 2 * here[i - Channels] + below[i - Channels]);
        const int gy = (below[i - Channels] + 2 * below[i] + below[i + Channels]) -
                       (above[i - Channels] + 2 * above[i] + above[i + Channels]);
        out[i] = gx * gx + gy * gy;
    }
}

template <int Channels>
void Preprocessor::compute_edges_of(const cv::Mat& source) noexcept {
    const int width = source.cols;
    const int height = source.rows;
    const int threshold = settings_.edge_threshold;
    int* const squared = squared_channels_.data();
    float* const strongest = strongest_.data();
    for (int y = 0; y < height; ++y) {
        squared_gradients<Channels>(
            source.ptr<std::uint8_t>(std::max(y - 1, 0)), source.ptr<std::uint8_t>(y),
            source.ptr<std::uint8_t>(std::min(y + 1, height - 1)), squared, width * Channels);
        for (int x = 0; x < width; ++x) {
            int value = squared[x * Channels];
            for (int c = 1; c < Channels; ++c)
                value = std::max(value, squared[x * Channels + c]);
            strongest[x] = static_cast<float>(value);
        }
        auto* magnitude = magnitude_.ptr<std::uint8_t>(y);
        auto* edge = edges_.ptr<std::uint8_t>(y);
        for (int x = 0; x < width; ++x) {
            const int value = static_cast<int>(std::min(255.0F, std::sqrt(strongest[x])));
            magnitude[x] = static_cast<std::uint8_t>(value);
            // Edge pixels keep their magnitude: the raster estimator climbs it to the ridge.
            edge[x] = value > threshold ? static_cast<std::uint8_t>(value) : 0;
        }
    }
}

}  // namespace raypoint::core
