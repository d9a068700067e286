// SPDX-License-Identifier: MIT
#pragma once
// The paper's whole system (section 4): frames with timestamps in, the target's projection
// features, the tracker state and a smoothed 3D position out.

#include <cstdint>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "raypoint/core/estimator.hpp"
#include "raypoint/core/frame.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/settings.hpp"
#include "raypoint/core/stage_instructions.hpp"
#include "raypoint/core/tracker_state.hpp"

namespace raypoint::core {

// Everything a frame produced. Fractions are of the input frame's width, height and area, so
// they do not depend on the working size or the camera's size.
struct FrameResult {
    std::int64_t frame = 0;
    Timestamp timestamp = 0;
    TrackerState state = TrackerState::initializing;  // after this frame
    bool has_target = false;
    cv::Point2d centroid;  // fractions; valid when has_target
    // When followed: the region's own centroid, whose area `area` is. The depth signal reads
    // it, as its jumps come with the region's steps, and the chain's point does not.
    cv::Point2d region_centroid;
    std::optional<double> area;  // fraction; unknown on the frame a search picks a target
    cv::Point2d inner;           // fractions; valid when has_target
    bool has_position = false;
    cv::Point3d position;   // smoothed x, y (fractions) and z (paper 4.3), when has_position
    double movement = 0.0;  // global inter-frame movement: sum of the compensated difference
    // The light's change since the previous frame that every band of rows shares, relative
    // (DifferenceStage::light_change()): a camera's gain jump; 0 under still light or flicker.
    double light_change = 0.0;
    int iterations = 0;      // estimator iterations spent on this frame
    bool recovered = false;  // RECOVERING ran this frame and succeeded
    bool held = false;       // the estimate grew too fast: the last one stands (max_growth)
    bool lost = false;       // the target was dropped this frame
    bool followed = false;   // the centroid is the movement's chain's (follow_movement)
    LossReason loss = LossReason::none;
    // Fractions: the failed inner point RECOVERING searched around this frame (for drawing).
    std::optional<cv::Point2d> recovery_from;
};

// The images of the last processed frame, for drawing and tests (working size).
struct TrackerImages {
    const cv::Mat& color;       // CV_8UC3 BGR, Poisson-filtered and subsampled
    const cv::Mat& edges;       // CV_8U Sobel magnitude
    const cv::Mat& difference;  // CV_8U compensated absolute difference
    const EstimatorTrace& trace;
};

class Tracker {
  public:
    // `instructions`: each preprocessing stage's set; every combination gives the same results.
    explicit Tracker(const Settings& settings, StageInstructions instructions =
                                                   StageInstructions::both(best_instruction_set()));
    ~Tracker();
    Tracker(const Tracker&) = delete;
    Tracker& operator=(const Tracker&) = delete;

    // Processes one frame. Never throws; does not allocate in steady state (same frame size).
    // Frames must come in timestamp order.
    FrameResult process(const FrameView& frame) noexcept;

    // From the next frame on; safe between any two frames, the results being the same
    // (the daemon measures them in turn while INITIALIZING, InstructionTrial).
    void set_instructions(StageInstructions instructions) noexcept;
    StageInstructions instructions() const noexcept;

    // The last processed frame's images. process() runs the edge stage only when the frame's
    // state machine step estimates (TRACKING, RECOVERING), so an idle tracker skips it; this
    // computes the edge image for any other frame (an edge stage's cost, results unchanged).
    TrackerImages images() const noexcept;
    // The same without the images: what the instruction trial times after process(), so
    // every candidate's edge set is measured on idle frames too.
    void ensure_edges() noexcept;
    // Whether the last processed frame's edge image has been computed (by its state machine
    // step, ensure_edges() or images()): false on INITIALIZING and SEARCHING frames.
    bool edges_computed() const noexcept;
    const Settings& settings() const noexcept;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace raypoint::core
