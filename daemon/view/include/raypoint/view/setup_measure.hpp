// SPDX-License-Identifier: MIT
#pragma once
// `raypoint setup`'s measurements: from the tracker's results over a guided run (hold still,
// move across the view, push a few times), the hand's size, the motion range and the push depth,
// and the settings they suggest. Frame time only, so a recorded run measures as it did live.

#include <optional>
#include <vector>

#include "raypoint/config/config.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::view {

struct SetupFigures {
    int tracked_frames = 0;
    double hand_area = 0.0;  // median area while tracked, fraction of the frame
    // The centroid's 5th and 95th percentiles while tracked, fractions of the frame.
    double left = 0.0, right = 1.0, top = 0.0, bottom = 1.0;
    std::vector<double> push_rises;  // each push's peak rise of sqrt(area) over its baseline
    double push_depth = 0.0;         // the median peak rise; 0 without pushes
};

struct SetupProposal {
    config::Config config;  // the starting configuration with the proposals applied
    SetupFigures figures;
};

class SetupMeasure {
  public:
    void add(const core::FrameResult& result);
    SetupFigures figures() const;
    // [pointer] gain, active_left/right/top/bottom, [click] press_rise and release_rise, from
    // the figures; `screen_width` in device pixels (relative mode's gain crosses the screen in
    // one sweep of the measured range). nullopt when too little was tracked to measure.
    std::optional<SetupProposal> propose(const config::Config& start, int screen_width) const;

  private:
    struct Sample {
        double t;
        double x, y;
        double scale;  // sqrt(area)
    };
    std::vector<Sample> samples_;
};

}  // namespace raypoint::view
