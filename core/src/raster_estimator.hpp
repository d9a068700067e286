// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "ray_estimators.hpp"

namespace raypoint::core::detail {

// Paper 3.4: iterative n^y-ray casting with m-rasterization.
class RasterEstimator final : public RayEstimatorBase {
  public:
    explicit RasterEstimator(const EstimatorSettings& settings);
    Estimate estimate(const cv::Mat& edges, cv::Point2f inner) noexcept override;
    void use_color(const cv::Mat* color) noexcept override { color_ = color; }
    void use_magnitude(const Magnitude& magnitude) noexcept override { magnitude_ = magnitude; }
    void forget_target() noexcept override { last_fill_ = 0; }
    Memory memory() const noexcept override { return last_fill_; }
    void restore(Memory memory) noexcept override { last_fill_ = memory; }

  private:
    Estimate estimate_on(const cv::Mat& edges, cv::Point2f inner) noexcept;
    // The edge image over EstimatorSettings::weak_edge_threshold, laid out as `edges` is (the
    // estimator's buffers index both alike); null when the magnitude does not fit `edges`.
    const cv::Mat* weak_edges(const cv::Mat& edges) noexcept;
    void resize(const cv::Mat& edges);
    void select_blocks() noexcept;
    cv::Point2f block_centroid() const noexcept;
    double block_area() const noexcept;
    // AreaMode::refined: area and centroid of the region the rays ran through, grown up to the
    // outline's ridge (docs/estimators.md).
    void refine(const cv::Mat& edges, Estimate& estimate) noexcept;
    bool fill(const cv::Mat& edges, bool within_blocks, double limit) noexcept;
    bool contains(cv::Point pixel) const noexcept {
        // One unsigned comparison an axis: negative coordinates wrap to large ones.
        return static_cast<unsigned>(pixel.x) < static_cast<unsigned>(width_) &&
               static_cast<unsigned>(pixel.y) < static_cast<unsigned>(height_);
    }
    // EstimatorSettings::neck_radius: the filled region loses what lies beyond a narrow neck.
    void cut_necks(cv::Point2f inner) noexcept;
    void morph(unsigned char from_bit, unsigned char to_bit, bool erode, int r, int x0, int y0,
               int x1, int y1) noexcept;
    void clear_marks(int x0, int y0, int x1, int y1) noexcept;
    std::size_t root(std::size_t run) noexcept;
    void unite(std::size_t a, std::size_t b) noexcept;
    void add_edge_band(const cv::Mat& edges, double& area, double& sum_x, double& sum_y) noexcept;
    // EstimatorSettings::extremity: a region that crosses the image border keeps its far end.
    void keep_extremity(Estimate& estimate, std::size_t inside_count) noexcept;
    // The region's pixels on the image border: how many, their centre, and the longest run of
    // them along the border (walked round it from the top-left corner, perimeter_position()).
    struct BorderContact {
        int pixels = 0;
        int longest_run = 0;
        cv::Point2d centre;
    };
    BorderContact border_contact(std::size_t inside_count) noexcept;
    int perimeter_position(cv::Point pixel) const noexcept;

    // filled_ values: 0 not reached, inside, or band + depth into the edge band.
    static constexpr unsigned char inside = 1;
    static constexpr unsigned char band = 2;

    const cv::Mat* color_ = nullptr;  // EstimatorSettings::diagonal_tolerance; not owned
    Magnitude magnitude_;             // EstimatorSettings::weak_edge_threshold; not owned
    std::vector<std::uint8_t> weak_pixels_;
    cv::Mat weak_edges_;         // a header on weak_pixels_, with the edge image's row step
    std::size_t last_fill_ = 0;  // pixels the last refined fill reached; 0 = none yet
    int width_ = 0;
    int height_ = 0;
    std::vector<int> block_of_column_;
    std::vector<int> block_of_row_;
    std::vector<unsigned char> ray_pixels_;  // 1 where a ray ran through, this frame
    std::size_t ray_pitch_ = 0;              // ray_pixels_'s row pitch: the edge image's step
    // The same pixels, each once, in order of first visit: the first ray_count_ of one slot a
    // pixel. The lists below are written through local pointers and counts: a store through an
    // unsigned char pointer may alias any member, which would be reloaded after each one.
    std::vector<cv::Point> ray_list_;
    std::size_t ray_count_ = 0;
    std::size_t blocks_listed_ = 0;         // the first this many have their blocks selected
    std::vector<int> selected_;             // indices of selected blocks, in selection order
    std::vector<unsigned char> filled_;     // refine(): 0 not reached, inside, or band + depth
    std::vector<unsigned char> on_border_;  // keep_extremity(): 1 a perimeter position reached
    // refine(): the first queued_ slots are the reached pixels, in order of reaching; a pixel is
    // queued at most once, so one slot a pixel always suffices.
    std::vector<cv::Point> queue_;
    // cut_necks(): bit marks a pixel (clear outside its call), a row pass's result, and a
    // queue of pixels, each sized to the image.
    std::vector<unsigned char> marks_;
    std::vector<unsigned char> run_;
    std::vector<int> column_counts_;
    // cut_necks(): runs of the core along the rows, [begin, end) on row y, joined by union-find.
    struct Run {
        int y;
        int begin;
        int end;
        std::size_t parent;
    };
    std::vector<Run> runs_;
    std::vector<cv::Point> work_;
    std::size_t queued_ = 0;
};

}  // namespace raypoint::core::detail
