// SPDX-License-Identifier: MIT
#pragma once
// The text and the plot of `raypoint eval-clicks`.

#include <cstdio>
#include <string>
#include <vector>

#include "click_eval.hpp"

namespace raypoint::daemon {

// A markdown table, one row a group of `tallies` (overall first, then the target pushes, the
// conditions, the motions and the bins).
void print_tallies(std::FILE* out, const Tallies& tallies);

// The right clicks, double clicks and scrolls of the "all" group: recognised, and taken for a
// left click; and the left clicks and drags taken for one of them.
void print_gestures(std::FILE* out, const Tallies& tallies);

// One point of a sweep: a label and its figures.
struct SweepPoint {
    std::string label;   // "press_rise 0.14"
    std::string series;  // points of one series are joined by a line
    double recall = 0;   // the target pushes that pressed
    double false_per_minute = 0;
};

void print_sweep(std::FILE* out, const std::vector<SweepPoint>& points);

// Recall against false clicks per minute, one polyline a series, written as PNG. Throws
// InputError when the file cannot be written.
void plot_sweep(const std::string& path, const std::vector<SweepPoint>& points);

}  // namespace raypoint::daemon
