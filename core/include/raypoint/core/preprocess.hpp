// SPDX-License-Identifier: MIT
#pragma once
// Frame preprocessing (paper 4.1): the three stages in order behind one interface. FilterStage
// (Poisson-disk filter and subsampling to the working size), EdgeStage (Sobel edge image) and
// DifferenceStage (brightness-compensated absolute difference and the global movement value).

#include "raypoint/core/difference_stage.hpp"
#include "raypoint/core/edge_stage.hpp"
#include "raypoint/core/filter_stage.hpp"
#include "raypoint/core/frame.hpp"
#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/poisson_disk.hpp"
#include "raypoint/core/settings.hpp"
#include "raypoint/core/stage_instructions.hpp"

namespace raypoint::core {

class Preprocessor {
  public:
    explicit Preprocessor(
        const PreprocessSettings& settings,
        StageInstructions instructions = StageInstructions::both(best_instruction_set()));

    // Returns false for a frame the core cannot read (null data, odd YUYV width, stride too
    // small, smaller than the working size): the frame is skipped, nothing changes.
    // Edges::deferred leaves the edge stage out until ensure_edges(): the Tracker's choice, as
    // only estimation (TRACKING, RECOVERING) reads the edge image, so an idle tracker skips it.
    enum class Edges { computed, deferred };
    bool process(const FrameView& frame, Edges edges = Edges::computed) noexcept;

    // process() is these three stages in order; they are public for the per-stage benchmarks
    // (core/perf) and do nothing else apart. filter() takes the frame as above (Poisson-disk
    // filter and subsampling to the colour, grey and channel images); the other two recompute
    // their images from the last filtered ones, so repeating them changes nothing.
    bool filter(const FrameView& frame) noexcept;
    void compute_edges() noexcept;
    void compute_difference() noexcept;

    // Runs the edge stage on the last filtered frame unless it already has: magnitude() and
    // edges() are then that frame's. edges_current() is false from a filtered frame until its
    // edges are computed (the images then still hold an older frame's, or zeros).
    void ensure_edges() noexcept {
        if (!edges_current_) compute_edges();
    }
    bool edges_current() const noexcept { return edges_current_; }

    // The filter's and the edge stage's sets, from the next frame on. Every combination gives
    // the same images, so they may change between any two frames (InstructionTrial).
    void set_instructions(StageInstructions instructions) noexcept;
    StageInstructions instructions() const noexcept {
        return {filter_.instructions(), edges_.instructions()};
    }

    const cv::Mat& color() const noexcept { return filter_.color(); }  // CV_8UC3
    // The previous frame's colour image; under Compensation::rows in this frame's light
    // (DifferenceStage::previous_color_relit()), so that the colour validation's comparison of
    // the two frames does not see mains flicker's bands as a change of colour.
    const cv::Mat& previous_color() const noexcept {
        return difference_.relit() ? difference_.previous_color_relit() : filter_.previous_color();
    }
    const cv::Mat& gray() const noexcept { return filter_.gray(); }  // CV_8U
    // The edge images are the last filtered frame's only when edges_current().
    const cv::Mat& magnitude() const noexcept { return edges_.magnitude(); }
    // CV_8U: the magnitude where it is over the edge threshold, 0 elsewhere.
    const cv::Mat& edges() const noexcept { return edges_.edges(); }
    const cv::Mat& difference() const noexcept { return difference_.difference(); }
    bool has_previous() const noexcept { return filter_.has_previous(); }
    // DifferenceStage::movement(): the sum of the compensated difference over the working
    // pixels (paper 4.1 "global inter-frame movement value").
    double movement() const noexcept { return difference_.movement(); }
    double light_change() const noexcept { return difference_.light_change(); }
    int brightness_offset_applied() const noexcept {
        return difference_.brightness_offset_applied();
    }

  private:
    FilterStage filter_;
    EdgeStage edges_;
    DifferenceStage difference_;
    bool edges_current_ = false;
};

}  // namespace raypoint::core
