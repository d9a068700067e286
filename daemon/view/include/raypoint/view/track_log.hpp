// SPDX-License-Identifier: MIT
#pragma once
// A track over time, as `raypoint plot` draws it: read back from `raypoint track`'s JSONL (and
// a file sink's events for the clicks), or collected while tracking (`track --plot`).

#include <filesystem>
#include <stdexcept>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/tracker_state.hpp"

namespace raypoint::view {

struct TrackSample {
    double t = 0.0;  // s, the frame's time
    core::TrackerState state = core::TrackerState::initializing;
    bool has_position = false;
    cv::Point3d position;  // smoothed x, y (fractions of the frame) and z (paper 4.3)
};

// A left button press or release, at a frame's time.
struct ClickMark {
    double t = 0.0;  // s
    bool press = true;
};

struct TrackLog {
    std::vector<TrackSample> samples;  // in time order
    std::vector<ClickMark> clicks;     // in time order
};

// A track file that cannot be read; the message names the file and line.
class TrackLogError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// `raypoint track --format jsonl` output. A line may carry "click":"press" or
// "click":"release"; those become clicks. Throws TrackLogError ("path:line: reason").
TrackLog read_track_jsonl(const std::filesystem::path& path);

// The BTN_LEFT lines of a file sink's events (`--sink file:PATH`, "t_us EV_KEY BTN_LEFT 1").
// Throws TrackLogError when the file cannot be read.
std::vector<ClickMark> read_sink_clicks(const std::filesystem::path& path);

}  // namespace raypoint::view
