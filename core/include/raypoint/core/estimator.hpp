// SPDX-License-Identifier: MIT
#pragma once
// Object projection feature estimation (paper section 3): from a binary edge image and a point
// inside the target's projection (the inner point), estimate the projection's centroid and area
// and move the inner point to where it is likeliest to stay inside in the next frame.

#include <array>
#include <cstddef>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/settings.hpp"

namespace raypoint::core {

// Everything in working-image pixels (pixel centres at integer coordinates).
struct Estimate {
    cv::Point2f centroid;
    double area = 0.0;  // square working pixels
    cv::Point2f inner;  // the relocated inner point
    int iterations = 0;
    // AreaMode::refined: the fill ran past its limit (fill_limit, fill_growth) and was redone
    // within the selected blocks: the outline has a gap the region ran out through.
    bool leaked = false;
    // EstimatorSettings::extremity: the region crosses the image border, and this is its far
    // end (centroid, area, and the inner point nearest that centroid). Whether it replaces the
    // whole is the caller's choice: the far end is the target when it moves (ImageEvidence).
    bool crosses_border = false;
    cv::Point2f end_centroid{};
    double end_area = 0.0;
    cv::Point2f end_inner{};
};

// One cast ray, kept for drawing (--annotate) and for tests.
struct RaySegment {
    cv::Point2f from;
    cv::Point2f to;
};

// What an estimator leaves behind besides its Estimate, for annotation.
struct EstimatorTrace {
    std::vector<RaySegment> rays;       // the last iteration's rays
    std::vector<unsigned char> blocks;  // raster only: selected blocks, row-major, 0 or 1
    int blocks_wide = 0;
    int blocks_high = 0;
    int block_size = 0;
};

class Estimator {
  public:
    virtual ~Estimator() = default;
    // edges: CV_8U, non-zero where there is an edge; the value is the edge strength (the Sobel
    // magnitude), which AreaMode::refined uses to find the outline's ridge. Does not allocate
    // once warmed up on a given image size.
    virtual Estimate estimate(const cv::Mat& edges, cv::Point2f inner) noexcept = 0;
    virtual const EstimatorTrace& trace() const noexcept = 0;
    // The colour image (CV_8UC3, the edge image's size) of the frame the next estimates are of,
    // for AreaMode::refined's diagonal steps (EstimatorSettings::diagonal_tolerance); it must
    // outlive those estimates. Without it the fill never steps diagonally.
    virtual void use_color(const cv::Mat* color) noexcept { (void)color; }
    // The Sobel magnitude (CV_8U, the edge image's size) of the frame the next estimates are
    // of, and the areas a target's projection can have (square working pixels), for
    // EstimatorSettings::weak_edge_threshold; it must outlive those estimates. Without it an
    // estimate is never redone on the weaker edges.
    struct Magnitude {
        const cv::Mat* image = nullptr;
        double smallest = 0.0;
        double largest = 0.0;
    };
    virtual void use_magnitude(const Magnitude& magnitude) noexcept { (void)magnitude; }
    // The target was dropped or a new one picked: what the estimator kept from the last frame's
    // estimate (EstimatorSettings::fill_growth) goes.
    virtual void forget_target() noexcept {}
    // What estimate() carries to the next frame's estimate of the same target (the refined
    // fill's size, EstimatorSettings::fill_growth). A look at another region that may not be
    // taken (a possible switch of target) restores it afterwards.
    using Memory = std::size_t;
    virtual Memory memory() const noexcept { return 0; }
    virtual void restore(Memory memory) noexcept { (void)memory; }
};

std::unique_ptr<Estimator> make_estimator(const EstimatorSettings& settings);

// Every estimator and its name, the one list of them: the names of --estimator and of the
// configuration's estimator.method, in the order they are offered.
inline constexpr std::array<std::pair<EstimatorKind, std::string_view>, 4> estimator_names{{
    {EstimatorKind::ray, "ray"},
    {EstimatorKind::iterative_ray, "iterative-ray"},
    {EstimatorKind::iterative_ny_ray, "iterative-ny-ray"},
    {EstimatorKind::raster, "raster"},
}};

// "ray", "iterative-ray", "iterative-ny-ray", "raster".
std::string_view to_string(EstimatorKind kind) noexcept;
bool estimator_from_string(std::string_view name, EstimatorKind& kind) noexcept;

}  // namespace raypoint::core
