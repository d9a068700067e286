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
    // Two passes over the pixels, no image: the histogram gives the offset and the sum, the
    // second pass the centre of mass of what is over the offset.
    const auto difference = [](const cv::Vec3b& a, const cv::Vec3b& b) {
        int largest = 0;
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(int{a[c]} - int{b[c]}));
        return largest;
    };
    std::array<std::int64_t, 256> histogram{};
    for (int y = 0; y < color.rows; ++y) {
        const auto* now = color.ptr<cv::Vec3b>(y);
        const auto* before = frame_.ptr<cv::Vec3b>(y);
        for (int x = 0; x < color.cols; ++x)
            ++histogram[static_cast<std::size_t>(difference(now[x], before[x]))];
    }
    int offset = 0;
    int distinct = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (histogram[static_cast<std::size_t>(value)] == 0) continue;
        offset = value;
        ++distinct;
    }
    double total = 0.0;
    for (int value = offset + 1; value < 256; ++value)
        total += static_cast<double>(histogram[static_cast<std::size_t>(value)]) * (value - offset);
    if (total <= threshold) return std::nullopt;
    double sum_x = 0.0;
    double sum_y = 0.0;
    for (int y = 0; y < color.rows; ++y) {
        const auto* now = color.ptr<cv::Vec3b>(y);
        const auto* before = frame_.ptr<cv::Vec3b>(y);
        for (int x = 0; x < color.cols; ++x) {
            const int weight = difference(now[x], before[x]) - offset;
            if (weight <= 0) continue;
            sum_x += static_cast<double>(weight) * x;
            sum_y += static_cast<double>(weight) * y;
        }
    }
    return cv::Point2f(static_cast<float>(sum_x / total), static_cast<float>(sum_y / total));
}

}  // namespace raypoint::core::detail
