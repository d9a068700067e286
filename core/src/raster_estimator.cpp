// SPDX-License-Identifier: MIT
#include "raster_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "estimator_common.hpp"

namespace raypoint::core::detail {

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
    weak_pixels_.assign(ray_pitch_ * static_cast<std::size_t>(height_), 0);
    weak_edges_ = cv::Mat(height_, width_, CV_8U, weak_pixels_.data(), ray_pitch_);
    on_border_.assign(2 * (static_cast<std::size_t>(width_) + static_cast<std::size_t>(height_)),
                      0);
    queue_.assign(pixels, cv::Point());
    // cut_necks()'s buffers, only when it runs (EstimatorSettings::neck_radius, off by default).
    if (settings_.neck_radius > 0) {
        marks_.assign(pixels, 0);
        run_.assign(pixels, 0);
        column_counts_.assign(static_cast<std::size_t>(width_), 0);
        // At most one run every two pixels of a row.
        runs_.assign(static_cast<std::size_t>(height_) * (static_cast<std::size_t>(width_) / 2 + 1),
                     Run{});
        work_.assign(pixels, cv::Point());
    }
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

// EstimatorSettings::weak_edge_threshold: an outline with gaps at the edge threshold may be
// whole on the weaker edges. The first estimate stands when the second leaks too, or is no
// target's size; the fill growth reference is then the first's, as if there was no second.
// A region that ran out through a gap into a closed region beyond (a wall between shelves)
// neither leaks nor grows past a target's size, but its centroid, and with it the inner point,
// moves into what lies beyond (weak_wander): the second is taken then only where it holds the
// inner point, so a region that wanders on the weaker edges too does not replace the first.
Estimate RasterEstimator::estimate(const cv::Mat& edges, cv::Point2f inner) noexcept {
    const std::size_t reference = last_fill_;
    const Estimate first = estimate_on(edges, inner);
    if (settings_.weak_edge_threshold <= 0 || magnitude_.image == nullptr ||
        settings_.area_mode != AreaMode::refined) {
        return first;
    }
    const auto wandered = [&](const Estimate& e) {
        return settings_.weak_wander > 0.0 && cv::norm(e.inner - inner) > settings_.weak_wander;
    };
    const bool failed = first.leaked || first.area > magnitude_.largest;
    if (!failed && !wandered(first)) return first;
    const cv::Mat* weak = weak_edges(edges);
    if (weak == nullptr) return first;
    const std::size_t first_fill = last_fill_;
    last_fill_ = reference;
    const Estimate second = estimate_on(*weak, inner);
    if (!second.leaked && second.area >= magnitude_.smallest && second.area <= magnitude_.largest &&
        (failed || !wandered(second))) {
        return second;
    }
    last_fill_ = first_fill;
    return first;
}

const cv::Mat* RasterEstimator::weak_edges(const cv::Mat& edges) noexcept {
    const cv::Mat& magnitude = *magnitude_.image;
    if (magnitude.size() != edges.size() || magnitude.type() != CV_8U || weak_edges_.empty() ||
        edges.cols != width_ || edges.rows != height_ || edges.step[0] != ray_pitch_) {
        return nullptr;
    }
    // Edge pixels keep their magnitude, as in the edge stage: the fill climbs it to the ridge.
    const int threshold = settings_.weak_edge_threshold;
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* from = magnitude.ptr<std::uint8_t>(y);
        std::uint8_t* to = weak_edges_.ptr<std::uint8_t>(y);
        for (int x = 0; x < width_; ++x)
            to[x] = from[x] > threshold ? from[x] : 0;
    }
    return &weak_edges_;
}

Estimate RasterEstimator::estimate_on(const cv::Mat& edges, cv::Point2f inner) noexcept {
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

void RasterEstimator::refine(const cv::Mat& edges, Estimate& estimate) noexcept {
    double limit = settings_.fill_limit * estimate.area;
    if (settings_.fill_growth > 0.0 && last_fill_ > 0)
        limit = std::min(limit, settings_.fill_growth * static_cast<double>(last_fill_));
    if (!fill(edges, false, limit)) {
        estimate.leaked = true;
        fill(edges, true, static_cast<double>(filled_.size()));
    }
    cut_necks(estimate.inner);
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

}  // namespace raypoint::core::detail
