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
        difference_.create(color.size(), CV_8U);
        depth_.create(color.size(), CV_16U);
    } catch (...) {
        frame_.release();
    }
}

std::optional<cv::Point2f> QuietFrame::change(const cv::Mat& color, double threshold,
                                              int minima) noexcept {
    if (frame_.empty() || frame_.size() != color.size() || frame_.type() != color.type() ||
        color.type() != CV_8UC3 || difference_.size() != color.size() ||
        depth_.size() != color.size()) {
        return std::nullopt;
    }
    // One pass over the pixels: each pixel's difference kept, and for each difference value its
    // count and the sums of its pixels' x and y. The offset comes from the counts; what is over
    // it weighs (value - offset), so the centre of mass is a sum over the values.
    std::array<std::int64_t, 256> count{};
    std::array<std::int64_t, 256> sum_x{};
    std::array<std::int64_t, 256> sum_y{};
    for (int y = 0; y < color.rows; ++y) {
        const auto* now = color.ptr<cv::Vec3b>(y);
        const auto* before = frame_.ptr<cv::Vec3b>(y);
        auto* kept = difference_.ptr<std::uint8_t>(y);
        for (int x = 0; x < color.cols; ++x) {
            int largest = 0;
            for (int c = 0; c < 3; ++c)
                largest = std::max(largest, std::abs(int{now[x][c]} - int{before[x][c]}));
            const auto value = static_cast<std::size_t>(largest);
            kept[x] = static_cast<std::uint8_t>(largest);
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
    const cv::Point2f centre(static_cast<float>(moment_x / total),
                             static_cast<float>(moment_y / total));
    return cv::Point2f(deepest(offset, centre));
}

cv::Point QuietFrame::deepest(int offset, cv::Point2f centre) noexcept {
    // Chamfer 3-4 in two passes: forward from the top-left neighbours, backward from the
    // bottom-right ones. Unchanged pixels are 0, as is everything outside the frame.
    constexpr int straight = 3;
    constexpr int diagonal = 4;
    const int rows = depth_.rows;
    const int cols = depth_.cols;
    const auto at = [&](int y, int x) -> int {
        if (y < 0 || y >= rows || x < 0 || x >= cols) return 0;
        return depth_.at<std::uint16_t>(y, x);
    };
    for (int y = 0; y < rows; ++y) {
        const auto* difference = difference_.ptr<std::uint8_t>(y);
        auto* depth = depth_.ptr<std::uint16_t>(y);
        for (int x = 0; x < cols; ++x) {
            if (difference[x] <= offset) {
                depth[x] = 0;
                continue;
            }
            const int d = std::min({at(y, x - 1) + straight, at(y - 1, x) + straight,
                                    at(y - 1, x - 1) + diagonal, at(y - 1, x + 1) + diagonal});
            depth[x] = static_cast<std::uint16_t>(d);
        }
    }
    cv::Point best(static_cast<int>(centre.x), static_cast<int>(centre.y));
    int best_depth = 0;
    float best_distance = 0.0F;
    for (int y = rows - 1; y >= 0; --y) {
        auto* depth = depth_.ptr<std::uint16_t>(y);
        for (int x = cols - 1; x >= 0; --x) {
            if (depth[x] == 0) continue;
            const int d = std::min({int{depth[x]}, at(y, x + 1) + straight, at(y + 1, x) + straight,
                                    at(y + 1, x + 1) + diagonal, at(y + 1, x - 1) + diagonal});
            depth[x] = static_cast<std::uint16_t>(d);
            const float dx = static_cast<float>(x) - centre.x;
            const float dy = static_cast<float>(y) - centre.y;
            const float distance = dx * dx + dy * dy;
            if (d > best_depth || (d == best_depth && distance < best_distance)) {
                best = {x, y};
                best_depth = d;
                best_distance = distance;
            }
        }
    }
    return best;
}

}  // namespace raypoint::core::detail
