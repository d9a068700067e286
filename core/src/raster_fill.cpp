// SPDX-License-Identifier: MIT
// The raster estimator's region: the flood fill from the rays' pixels and the edge band that
// puts the outline on the ridge of the edges (RasterEstimator::fill, add_edge_band).
#include "raster_estimator.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "estimator_common.hpp"

namespace raypoint::core::detail {

namespace {

// Left, right, up, down: the order the fills queue a pixel's neighbours in.
struct Step {
    int x;
    int y;
};
constexpr std::array<Step, 4> neighbour_steps{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}};
// The fill's steps: the four neighbours, then the four diagonal ones (same_color()).
constexpr std::array<Step, 8> fill_steps{
    {{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}}};

// A diagonal step the four neighbours could not make crosses a one-pixel diagonal line of edge
// pixels; it joins the two sides only where they have one colour (a finger's middle and the
// palm), not where an outline's gap runs between a hand and the wall behind it. `a` and `b`
// are BGR pixels.
bool same_color(const std::uint8_t* a, const std::uint8_t* b, int tolerance) noexcept {
    const int distance = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
    return distance <= tolerance;
}

// The image's size, and the pixels all eight neighbours of which are in it: x - 1 < w - 2 and
// y - 1 < h - 2, unsigned.
struct Bounds {
    int w;
    int h;
    unsigned inner_w = static_cast<unsigned>(std::max(w - 2, 0));
    unsigned inner_h = static_cast<unsigned>(std::max(h - 2, 0));
};

// Calls step(s) for each neighbour_steps[s] from `pixel` that stays in the image, in that order.
// Off the border every step does, and the calls are spelled out: each step's offsets are
// constants.
template <typename StepTo>
void each_neighbour(cv::Point pixel, Bounds bounds, const StepTo& step) noexcept {
    if (static_cast<unsigned>(pixel.x - 1) < bounds.inner_w &&
        static_cast<unsigned>(pixel.y - 1) < bounds.inner_h) {
        step(0);
        step(1);
        step(2);
        step(3);
        return;
    }
    for (std::size_t s = 0; s < neighbour_steps.size(); ++s) {
        const int x = pixel.x + neighbour_steps[s].x;
        const int y = pixel.y + neighbour_steps[s].y;
        if (static_cast<unsigned>(x) < static_cast<unsigned>(bounds.w) &&
            static_cast<unsigned>(y) < static_cast<unsigned>(bounds.h)) {
            step(s);
        }
    }
}

// Four bytes from `p`, in memory order.
std::uint32_t load4(const std::uint8_t* p) noexcept {
    std::uint32_t word = 0;
    std::memcpy(&word, p, sizeof word);
    return word;
}

// Whether a byte of `word` is zero (exact: a borrow only runs on from a zero byte).
constexpr bool has_zero_byte(std::uint32_t word) noexcept {
    return ((word - 0x01010101U) & ~word & 0x80808080U) != 0;
}

// The byte at memory position `i` of a load4() word set, whatever the byte order.
constexpr std::uint32_t byte_at(std::size_t i) noexcept {
    std::array<std::uint8_t, 4> bytes{};
    bytes[i] = 0xFF;
    return std::bit_cast<std::uint32_t>(bytes);
}
constexpr std::uint32_t first_byte = byte_at(0);
constexpr std::uint32_t last_byte = byte_at(3);

}  // namespace

// Flood fill from every pixel a ray ran through, bounded by edges. A gap in the outline lets
// the fill leak into the background: past fill_limit x the selected blocks' area the fill
// starts over restricted to the selected blocks, the region the rays vouch for.
bool RasterEstimator::fill(const cv::Mat& edges, bool within_blocks, double limit) noexcept {
    std::fill(filled_.begin(), filled_.end(), 0);
    const int w = width_;
    const int h = height_;
    unsigned char* const filled = filled_.data();
    cv::Point* const queue = queue_.data();
    std::size_t count = 0;
    // The seeds come in order of first visit, not row by row: the filled set does not depend on
    // the order, nor does the test against `limit` (the queue only grows, so it exceeds the limit
    // at some point exactly when the whole filled set does), nor the exact sums of refine().
    for (std::size_t i = 0; i < ray_count_; ++i) {
        const cv::Point pixel = ray_list_[i];
        filled[static_cast<std::ptrdiff_t>(pixel.y) * w + pixel.x] = inside;
        queue[count++] = pixel;
    }
    // count > cap exactly when count > limit: the counts are integers under 2^53, exact in double.
    std::size_t cap = std::numeric_limits<std::size_t>::max();  // also for a NaN limit
    if (limit < 0.0) {
        if (count > 0) {
            queued_ = count;
            return false;
        }
    } else if (limit < 0x1p53) {
        cap = static_cast<std::size_t>(limit);
    }
    const bool colors = color_ != nullptr && settings_.diagonal_tolerance > 0 &&
                        color_->cols == width_ && color_->rows == height_;
    const std::size_t steps = colors ? fill_steps.size() : neighbour_steps.size();
    const std::uint8_t* const edge = edges.data;
    const auto edge_stride = static_cast<std::ptrdiff_t>(edges.step[0]);
    const std::uint8_t* const color = colors ? color_->data : nullptr;
    const auto color_stride = colors ? static_cast<std::ptrdiff_t>(color_->step[0]) : 0;
    const int tolerance = settings_.diagonal_tolerance;
    const unsigned char* const blocks = trace_.blocks.data();
    const int blocks_wide = trace_.blocks_wide;
    const int* const block_of_row = block_of_row_.data();
    const int* const block_of_column = block_of_column_.data();
    // Each step's offset in filled_, edges and the colour image.
    std::array<std::ptrdiff_t, fill_steps.size()> filled_offset{};
    std::array<std::ptrdiff_t, fill_steps.size()> edge_offset{};
    std::array<std::ptrdiff_t, fill_steps.size()> color_offset{};
    for (std::size_t s = 0; s < fill_steps.size(); ++s) {
        filled_offset[s] = static_cast<std::ptrdiff_t>(fill_steps[s].y) * w + fill_steps[s].x;
        edge_offset[s] = fill_steps[s].y * edge_stride + fill_steps[s].x;
        color_offset[s] = fill_steps[s].y * color_stride + 3 * fill_steps[s].x;
    }
    for (std::size_t head = 0; head < count; ++head) {
        if (count > cap) {
            queued_ = count;
            return false;
        }
        const cv::Point pixel = queue[head];
        const std::ptrdiff_t here = static_cast<std::ptrdiff_t>(pixel.y) * w + pixel.x;
        const std::ptrdiff_t edge_here = pixel.y * edge_stride + pixel.x;
        // Off the border every step stays in the image.
        const bool interior = pixel.x > 0 && pixel.y > 0 && pixel.x < w - 1 && pixel.y < h - 1;
        // Most pixels are ray pixels amid others or against the outline: every step would find
        // its pixel reached, or (the eight steps) an edge. The eight are read four bytes a row,
        // the byte outside the 3x3 ignored: x - 1 to x + 2 above and on the pixel's row, x - 2
        // to x + 1 below, all within the images off their border.
        if (interior) {
            const unsigned char* const f = filled + here;
            const std::uint8_t* const e = edge + edge_here;
            if (colors
                    ? !has_zero_byte(load4(f - w - 1) | load4(e - edge_stride - 1) | last_byte) &&
                          !has_zero_byte(load4(f - 1) | load4(e - 1) | last_byte) &&
                          !has_zero_byte(load4(f + w - 2) | load4(e + edge_stride - 2) | first_byte)
                    : f[-1] != 0 && f[1] != 0 && f[-w] != 0 && f[w] != 0) {
                continue;
            }
        }
        for (std::size_t s = 0; s < steps; ++s) {
            const Step step = fill_steps[s];
            const cv::Point next(pixel.x + step.x, pixel.y + step.y);
            if (!interior && !contains(next)) continue;
            const std::ptrdiff_t index = here + filled_offset[s];
            if (filled[index] != 0 || edge[edge_here + edge_offset[s]] != 0) continue;
            if (s >= neighbour_steps.size()) {
                const std::uint8_t* from = color + pixel.y * color_stride + 3 * pixel.x;
                if (!same_color(from, from + color_offset[s], tolerance)) continue;
            }
            if (within_blocks &&
                blocks[block_of_row[next.y] * blocks_wide + block_of_column[next.x]] == 0) {
                continue;
            }
            filled[index] = inside;
            queue[count++] = next;
        }
    }
    queued_ = count;
    return true;
}

// The outline is the ridge of the edge band, not its inner side: from the filled region, climb
// the band while the edge strength does not fall, at most band_depth pixels; climbed pixels
// count whole, ridge pixels (no stronger neighbour) half, as the outline runs through them.
void RasterEstimator::add_edge_band(const cv::Mat& edges, double& area, double& sum_x,
                                    double& sum_y) noexcept {
    constexpr int band_depth = 3;
    const int w = width_;
    const int h = height_;
    unsigned char* const filled = filled_.data();
    cv::Point* const queue = queue_.data();
    std::size_t count = queued_;
    const std::size_t inside_count = count;
    const Bounds bounds{w, h};
    const std::uint8_t* const edge = edges.data;
    const auto edge_stride = static_cast<std::ptrdiff_t>(edges.step[0]);
    std::array<std::ptrdiff_t, neighbour_steps.size()> filled_offset{};
    std::array<std::ptrdiff_t, neighbour_steps.size()> edge_offset{};
    for (std::size_t s = 0; s < neighbour_steps.size(); ++s) {
        filled_offset[s] =
            static_cast<std::ptrdiff_t>(neighbour_steps[s].y) * w + neighbour_steps[s].x;
        edge_offset[s] = neighbour_steps[s].y * edge_stride + neighbour_steps[s].x;
    }
    // The inside pixels climb one step into the band: to a neighbour not reached that is an
    // edge (strength > 0 >= the inside's strength 0, at depth 0).
    for (std::size_t head = 0; head < inside_count; ++head) {
        const cv::Point pixel = queue[head];
        const std::ptrdiff_t index_here = static_cast<std::ptrdiff_t>(pixel.y) * w + pixel.x;
        const std::ptrdiff_t edge_here = pixel.y * edge_stride + pixel.x;
        const auto enter = [&](std::size_t s) {
            const std::ptrdiff_t index = index_here + filled_offset[s];
            if (filled[index] != 0 || edge[edge_here + edge_offset[s]] == 0) return;
            filled[index] = band + 1;
            queue[count++] = {pixel.x + neighbour_steps[s].x, pixel.y + neighbour_steps[s].y};
        };
        each_neighbour(pixel, bounds, enter);
    }
    // The band's pixels climb on while the strength does not fall, and count.
    for (std::size_t head = inside_count; head < count; ++head) {
        const cv::Point pixel = queue[head];
        const std::ptrdiff_t index_here = static_cast<std::ptrdiff_t>(pixel.y) * w + pixel.x;
        const std::ptrdiff_t edge_here = pixel.y * edge_stride + pixel.x;
        const int depth = filled[index_here] - band;
        const int strength = edge[edge_here];
        bool ridge = true;
        const auto climb = [&](std::size_t s) {
            const int next_strength = edge[edge_here + edge_offset[s]];
            if (next_strength > strength) ridge = false;
            const std::ptrdiff_t index = index_here + filled_offset[s];
            if (filled[index] != 0 || next_strength == 0 || next_strength < strength ||
                depth >= band_depth) {
                return;
            }
            filled[index] = static_cast<unsigned char>(band + depth + 1);
            queue[count++] = {pixel.x + neighbour_steps[s].x, pixel.y + neighbour_steps[s].y};
        };
        each_neighbour(pixel, bounds, climb);
        const double weight = ridge ? 0.5 : 1.0;
        area += weight;
        sum_x += weight * pixel.x;
        sum_y += weight * pixel.y;
    }
    queued_ = count;
}

}  // namespace raypoint::core::detail
