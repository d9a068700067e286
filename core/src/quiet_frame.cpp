// SPDX-License-Identifier: MIT
#include "quiet_frame.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>

namespace raypoint::core::detail {

void QuietFrame::keep(const cv::Mat& color) noexcept {
    try {
        color.copyTo(frame_);
    } catch (...) {
        frame_.release();
    }
}

std::optional<cv::Point2f> QuietFrame::change(const cv::Mat& color, double threshold,
                                              int minima) noexcept {
    if (frame_.empty() || frame_.size() != color.size() || frame_.type() != color.type() ||
        color.type() != CV_8UC3) {
        return std::nullopt;
    }
    // One pass over the pixels, no image: for each difference value its count and the sums of
    // its pixels' x and y. The offset comes from the counts; what is over it weighs
    // (value - offset), so the centre of mass is a sum over the values, not a second pass.
    std::array<std::int64_t, 256> count{};
    std::array<std::int64_t, 256> sum_x{};
    std::array<std::int64_t, 256> sum_y{};
    for (int y = 0; y < color.rows; ++y) {
        const auto* now = color.ptr<cv::Vec3b>(y);
        const auto* before = frame_.ptr<cv::Vec3b>(y);
        for (int x = 0; x < color.cols; ++x) {
            int largest = 0;
            for (int c = 0; c < 3; ++c)
                largest = std::max(largest, std::abs(int{now[x][c]} - int{before[x][c]}));
            const auto value = static_cast<std::size_t>(largest);
            ++count[value];
            sum_x[value] += x;
            sum_y[value] += y;
        }
    }
    int offset = 0;
    int distinct = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (count[static_cast<std::size_t>(value)] == 0) continue;
        offset = value;
        ++distinct;
    }
    double total = 0.0;
    double moment_x = 0.0;
    double moment_y = 0.0;
    for (int value = offset + 1; value < 256; ++value) {
        const auto v = static_cast<std::size_t>(value);
        const auto weight = static_cast<double>(value - offset);
        total += static_cast<double>(count[v]) * weight;
        moment_x += static_cast<double>(sum_x[v]) * weight;
        moment_y += static_cast<double>(sum_y[v]) * weight;
    }
    if (total <= threshold) return std::nullopt;
    return cv::Point2f(static_cast<float>(moment_x / total), static_cast<float>(moment_y / total));
}

}  // namespace raypoint::core::detail
