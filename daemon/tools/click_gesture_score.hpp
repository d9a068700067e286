// SPDX-License-Identifier: MIT
#pragma once
// What the pointer did in an intended gesture's span, and whether that was the gesture: the
// right click, double click and scroll of eval-clicks (click_eval.cpp scores the left clicks).

#include <optional>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "click_eval.hpp"
#include "raypoint/scene/gesture_set.hpp"

namespace raypoint::daemon {

// A press counts for an intended click from the push's start until this long after its
// intended release: a late press is still that push's, not a false click.
inline constexpr double match_slack = 0.3;  // s

struct Press {
    double at = 0;
    std::optional<double> released;
    bool dragged = false;
    cv::Point2d cursor;    // after the press's own motion (the undo)
    bool doubled = false;  // came after a whole click in the same command: a double click
};

// What a clip's intended gesture got from the pointer, besides the left presses.
struct Outputs {
    std::vector<double> rights;                 // s: right presses
    std::vector<std::pair<double, int>> wheel;  // s, hi-res units (1/120 detent)
};

struct GestureScore {
    bool found = false;
    bool as_left = false;
    std::optional<double> at;  // the gesture's press or first wheel step
};

bool any_in(const std::vector<double>& times, double from, double to);
// The wheel's sum over [from, to] and when it first moved (or nothing).
std::pair<int, std::optional<double>> wheel_in(const Outputs& out, double from, double to);
// A right click, double click or scroll against what the pointer did in its span; the left
// presses in the span are this gesture's (used), right or wrong.
GestureScore score_gesture(const scene::IntendedClick& g, const std::vector<Press>& presses,
                           std::vector<bool>& used, const Outputs& out);
GestureTally& gesture_tally(Tally& tally, scene::GestureKind kind);

}  // namespace raypoint::daemon
