// SPDX-License-Identifier: MIT
#include "raster_estimator.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
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

RasterEstimator::RasterEstimator(const EstimatorSettings& settings) : RayEstimatorBase(settings) {}

void RasterEstimator::resize(const cv::Mat& edges) {
    // The lists index the old size's pixels and blocks.
    selected_.clear();
    ray_count_ = 0;
    blocks_listed_ = 0;
    queued_ = 0;
    width_ = edges.cols;
    height_ = edges.rows;
    const int m = settings_.block_size;
    trace_.block_size = m;
    trace_.blocks_wide = (width_ + m - 1) / m;
    trace_.blocks_high = (height_ + m - 1) / m;
    block_of_column_.resize(static_cast<std::size_t>(width_));
    block_of_row_.resize(static_cast<std::size_t>(height_));
    for (int x = 0; x < width_; ++x)
        block_of_column_[x] = x / m;
    for (int y = 0; y < height_; ++y)
        block_of_row_[y] = y / m;
    const auto pixels = static_cast<std::size_t>(width_) * height_;
    trace_.blocks.assign(static_cast<std::size_t>(trace_.blocks_wide) * trace_.blocks_high, 0);
    selected_.reserve(trace_.blocks.size());
    // Indexed like the edge image's bytes (RayCaster::cast's offsets), rows `edges.step` apart.
    ray_pitch_ = edges.step[0];
    ray_pixels_.assign(ray_pitch_ * static_cast<std::size_t>(height_), 0);
    ray_list_.assign(pixels, cv::Point());
    filled_.assign(pixels, 0);
    queue_.assign(pixels, cv::Point());
}

// A pixel's block is selected for the pixel's first visit, so later visits change nothing. The
// blocks of the pixels listed since the last call are selected in order of first visit, the
// order selecting them during the casts would give.
void RasterEstimator::select_blocks() noexcept {
    for (; blocks_listed_ < ray_count_; ++blocks_listed_) {
        const cv::Point pixel = ray_list_[blocks_listed_];
        const int block = block_of_row_[pixel.y] * trace_.blocks_wide + block_of_column_[pixel.x];
        if (trace_.blocks[block] == 0) {
            trace_.blocks[block] = 1;
            selected_.push_back(block);
        }
    }
}

// Block centres are the centres of the pixels a block really has (the last row and column of
// blocks may be cut by the image border), in pixel-centre coordinates.
cv::Point2f RasterEstimator::block_centroid() const noexcept {
    double x = 0.0;
    double y = 0.0;
    double weight = 0.0;
    const int m = settings_.block_size;
    for (const int block : selected_) {
        const int bx = (block % trace_.blocks_wide) * m;
        const int by = (block / trace_.blocks_wide) * m;
        const int w = std::min(m, width_ - bx);
        const int h = std::min(m, height_ - by);
        const double area = static_cast<double>(w) * h;
        x += area * (bx + (w - 1) * 0.5);
        y += area * (by + (h - 1) * 0.5);
        weight += area;
    }
    if (weight == 0.0) return {};
    return {static_cast<float>(x / weight), static_cast<float>(y / weight)};
}

double RasterEstimator::block_area() const noexcept {
    double area = 0.0;
    const int m = settings_.block_size;
    for (const int block : selected_) {
        const int bx = (block % trace_.blocks_wide) * m;
        const int by = (block / trace_.blocks_wide) * m;
        area += static_cast<double>(std::min(m, width_ - bx)) * std::min(m, height_ - by);
    }
    return area;
}

Estimate RasterEstimator::estimate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    if (edges.cols != width_ || edges.rows != height_ || edges.step[0] != ray_pitch_) {
        try {
            resize(edges);
        } catch (...) {
            return Estimate{inner, 0.0, inner, 0};
        }
    }
    // Blocks are never unselected within a frame (paper 3.4), so the centroid converges.
    for (const int block : selected_)
        trace_.blocks[block] = 0;
    selected_.clear();
    for (std::size_t i = 0; i < ray_count_; ++i)
        ray_pixels_[static_cast<std::size_t>(ray_list_[i].y) * ray_pitch_ + ray_list_[i].x] = 0;
    ray_count_ = 0;
    blocks_listed_ = 0;
    // Called for every pixel every ray runs through (thousands a frame, most of them again): a
    // repeated pixel returns at once, a new one is listed, its block selected after the casts
    // (select_blocks()). No call: a call would have the caster's registers saved around it.
    unsigned char* const ray_pixels = ray_pixels_.data();
    const auto visit = [this, ray_pixels](int x, int y, std::size_t offset) {
        unsigned char& visited = ray_pixels[offset];
        if (visited != 0) return;
        visited = 1;
        ray_list_[ray_count_++] = cv::Point(x, y);
    };
    inner = RayCaster::off_edge(edges, inner, settings_.edge_escape);

    Estimate result;
    Convergence convergence(settings_.tolerance);
    for (int i = 0; i < settings_.max_iterations; ++i) {
        trace_.rays.clear();
        cast_levels(caster_, edges, inner, settings_.recasts, hits_, scratch_, &trace_.rays, visit);
        select_blocks();
        result.centroid = block_centroid();
        const cv::Point2f walked = RayCaster::walk(edges, inner, result.centroid);
        relocation_.clear();
        caster_.cast(edges, walked, relocation_, visit);
        for (const auto& hit : relocation_)
            trace_.rays.push_back({walked, hit.point});
        const cv::Point2f moved = RayCaster::walk(edges, walked, mean_point(relocation_));
        result.iterations = i + 1;
        const bool settled = convergence.settled(result.centroid, inner, moved);
        inner = moved;
        if (settled) break;
    }
    select_blocks();
    result.centroid = block_centroid();
    result.area = block_area();
    result.inner = inner;
    switch (settings_.area_mode) {
        case AreaMode::blocks:
            break;
        case AreaMode::refined:
            refine(edges, result);
            break;
    }
    return result;
}

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

void RasterEstimator::refine(const cv::Mat& edges, Estimate& estimate) noexcept {
    double limit = settings_.fill_limit * estimate.area;
    if (settings_.fill_growth > 0.0 && last_fill_ > 0)
        limit = std::min(limit, settings_.fill_growth * static_cast<double>(last_fill_));
    if (!fill(edges, false, limit)) {
        fill(edges, true, static_cast<double>(filled_.size()));
    }
    last_fill_ = queued_;
    // Integer sums: each partial sum is an integer under 2^53, so summing in double gives
    // the same values.
    std::int64_t inside_x = 0;
    std::int64_t inside_y = 0;
    for (std::size_t i = 0; i < queued_; ++i) {
        inside_x += queue_[i].x;
        inside_y += queue_[i].y;
    }
    double area = static_cast<double>(queued_);
    auto sum_x = static_cast<double>(inside_x);
    auto sum_y = static_cast<double>(inside_y);
    const std::size_t inside_count = queued_;
    add_edge_band(edges, area, sum_x, sum_y);
    if (area <= 0.0) return;
    estimate.area = area;
    estimate.centroid = {static_cast<float>(sum_x / area), static_cast<float>(sum_y / area)};
    if (settings_.extremity > 0.0) keep_extremity(estimate, inside_count);
}

// A region that runs over the image border is a limb, or a body, coming in from outside the
// picture: what points is its far end (the hand at the end of an arm, the ball a hand holds up).
// The region's pixels beyond `extremity` of the farthest one's distance from where it crosses
// the border are that end; its inner point is the one of them nearest their centroid.
void RasterEstimator::keep_extremity(Estimate& estimate, std::size_t inside_count) const noexcept {
    double contact = 0.0;
    double contact_x = 0.0;
    double contact_y = 0.0;
    // On the border: not x - 1 < w - 2 and y - 1 < h - 2, unsigned.
    const auto inner_w = static_cast<unsigned>(std::max(width_ - 2, 0));
    const auto inner_h = static_cast<unsigned>(std::max(height_ - 2, 0));
    for (std::size_t i = 0; i < inside_count; ++i) {
        const cv::Point p = queue_[i];
        if (static_cast<unsigned>(p.x - 1) >= inner_w ||
            static_cast<unsigned>(p.y - 1) >= inner_h) {
            contact += 1.0;
            contact_x += p.x;
            contact_y += p.y;
        }
    }
    if (contact < settings_.extremity_contact) return;
    const cv::Point2d base(contact_x / contact, contact_y / contact);
    const auto distance = [&](cv::Point p) { return std::hypot(p.x - base.x, p.y - base.y); };
    double farthest = 0.0;
    for (std::size_t i = 0; i < inside_count; ++i)
        farthest = std::max(farthest, distance(queue_[i]));
    const double reach = settings_.extremity * farthest;
    double area = 0.0;
    double sum_x = 0.0;
    double sum_y = 0.0;
    for (std::size_t i = 0; i < inside_count; ++i) {
        if (distance(queue_[i]) < reach) continue;
        area += 1.0;
        sum_x += queue_[i].x;
        sum_y += queue_[i].y;
    }
    if (area <= 0.0) return;
    const cv::Point2f centroid(static_cast<float>(sum_x / area), static_cast<float>(sum_y / area));
    cv::Point2f inner = estimate.inner;
    double nearest = -1.0;
    for (std::size_t i = 0; i < inside_count; ++i) {
        const cv::Point p = queue_[i];
        if (distance(p) < reach) continue;
        const double d = std::hypot(p.x - static_cast<double>(centroid.x),
                                    p.y - static_cast<double>(centroid.y));
        if (nearest < 0.0 || d < nearest) {
            nearest = d;
            inner = cv::Point2f(static_cast<float>(p.x), static_cast<float>(p.y));
        }
    }
    // The part's share of the region's outline band is not known: its area is the inside pixels,
    // scaled by the whole region's band-to-inside ratio.
    estimate.crosses_border = true;
    estimate.end_area = area * estimate.area / static_cast<double>(inside_count);
    estimate.end_centroid = centroid;
    estimate.end_inner = inner;
}

}  // namespace raypoint::core::detail
