// SPDX-License-Identifier: MIT
#pragma once
// `raypoint eval-clicks`: the tracker once over each clip, then the pointer (the daemon's own
// core::PointerController, with any click settings) over the tracker's results, scored against
// the clip's intended presses and releases. Tracking does not depend on the click settings, so
// a sweep over them replays the pointer only.

#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "raypoint/core/pointer_settings.hpp"
#include "raypoint/core/settings.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/scene/gesture_set.hpp"

namespace raypoint::daemon {

struct TrackedClip {
    std::string name;
    std::string motion;  // "push", a non-push motion, or "recorded"
    std::vector<std::pair<std::string, std::string>> conditions;
    std::vector<scene::IntendedClick> clicks;
    std::vector<std::pair<double, double>> motion_spans;  // s: non-push motion, for false clicks
    std::vector<std::pair<double, double>> approaches;    // s: push-fast, unmeant; not scored
    double aspect = 4.0 / 3.0;                            // frame width / height
    double seconds = 0;
    std::vector<core::FrameResult> results;  // one a frame, in order
};

// The clip's truth, without results.
TrackedClip track_rendered_truth(const scene::GestureClip& clip);

// Renders the clip and runs the tracker over it.
TrackedClip track_rendered(const scene::GestureClip& clip, const core::Settings& settings);

// A recorded video (as for `raypoint run --input`) and its truth file (gesture_set.hpp's
// format). Throws InputError.
TrackedClip track_recorded(const std::string& video, const std::string& truth,
                           const core::Settings& settings);

// A right click, double click or scroll: how many, how many recognised, and how many taken for
// a left click (a left press in the gesture's span without the gesture).
struct GestureTally {
    int count = 0;
    int found = 0;
    int as_left = 0;
    std::vector<double> latencies;  // s, push start -> the gesture's press or first wheel step

    void add(const GestureTally& other);
};

// How the pointer did on a set of clips, for one group (a condition, or everything).
struct Tally {
    int clicks = 0;        // intended
    int clicks_found = 0;  // pressed and released before a drag began
    int drags = 0;
    int drags_found = 0;     // pressed and held into a drag
    int pushes_pressed = 0;  // intended clicks and drags with a press at all
    int presses = 0;         // all presses in push clips
    int matched = 0;         // of those, one for an intended click or drag
    double motion_seconds = 0;
    int false_clicks = 0;  // presses during non-push motion
    // Approaches in motion clips as fast as a push (scene/approaches.hpp), and how many of them
    // pressed: neither false clicks nor pushes.
    int approaches = 0;
    int approaches_pressed = 0;
    std::vector<double> latencies;  // s, push start -> press
    std::vector<double> offsets;    // device px, cursor at the press - cursor at push start
    // Intended clicks and drags that came out as another gesture: a right press, a double
    // click or the wheel in their span.
    int left_as_other = 0;
    int false_wheel = 0;  // wheel steps during non-push motion
    GestureTally right;
    GestureTally double_click;
    GestureTally scroll;

    void add(const Tally& other);
    int gestures() const { return clicks + drags; }
    double press_recall() const;
    double precision() const;
    double false_per_minute() const;
};

// Groups: "all", "target" (pushes >= 15% closer within 0.6 s), each "key=value" condition,
// "motion=..." and the depth and duration bins of the pushes.
using Tallies = std::map<std::string, Tally>;

// The pointer over one tracked clip; adds to `tallies`. `misses`: a line for each intended
// press missed and each false or unmatched press, with what the tracker and the rise did.
// `trace`: a header and a line for each frame of the clip named `trace_clip`. `output`: the
// smoothing the results' positions came through (the tracker's).
void score_clip(const TrackedClip& clip, const core::PointerSettings& settings,
                const core::OutputSettings& output, Tallies& tallies, std::FILE* misses = nullptr,
                std::FILE* trace = nullptr, std::string_view trace_clip = {});

double median(std::vector<double> values);  // NaN when empty

}  // namespace raypoint::daemon
