// SPDX-License-Identifier: MIT
#pragma once
// Click by dwelling (click.mode = dwell): the cursor held within a radius for a time clicks
// once; the next click needs a move out of the radius first. A small state machine, drawn in
// docs/pointer.md. Frame time only, no allocation.

#include <optional>
#include <string_view>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

enum class DwellState {
    inactive,  // no target, or tracked for less than min_tracking_seconds
    waiting,   // within the radius of the anchor since `since`: clicks after dwell seconds
    clicked,   // clicked at the anchor: waits for a move out of the radius
};

std::string_view to_string(DwellState state) noexcept;

class DwellClicker {
  public:
    explicit DwellClicker(const DwellSettings& settings) noexcept;

    // where: the target's position in frame widths on both axes, or nullopt without a target.
    // Returns true when this frame clicks (a press and its release).
    bool step(Timestamp timestamp, std::optional<cv::Point2d> where, bool ready) noexcept;
    void reset() noexcept { state_ = DwellState::inactive; }

    DwellState state() const noexcept { return state_; }

  private:
    bool moved(cv::Point2d where) const noexcept;

    DwellSettings settings_;
    DwellState state_ = DwellState::inactive;
    cv::Point2d anchor_;
    Timestamp since_ = 0;
};

}  // namespace raypoint::core
