// SPDX-License-Identifier: MIT
#pragma once
// The exact ground truth of one rendered frame, measured on the target's mask.

#include <opencv2/core.hpp>

namespace raypoint::scene {

// Positions and sizes are fractions of the frame (resolution-free): pixel (i, j) has its
// centre at ((i + 0.5) / width, (j + 0.5) / height), and the frame spans 0..1 both ways.
struct Truth {
    int frame = 0;
    double t = 0;          // s, the middle of the frame's exposure
    bool present = false;  // at least one pixel of the target is visible
    // The visible target's centroid moved more than moving_centroid_px pixels at 160x120, or
    // its area changed by more than moving_area_change (relative), since the previous frame.
    // False when the previous frame had no target.
    bool moving = false;
    double cx = 0;  // centroid of the visible pixels
    double cy = 0;
    double area = 0;  // visible pixels / (width x height)
    double bx = 0;    // bounding box: left and top edges, width and height
    double by = 0;
    double bw = 0;
    double bh = 0;
    double depth = 0;  // m, the target centre's distance at t (0 when absent)
};

constexpr double moving_centroid_px = 0.25;  // pixels of a 160x120 image
constexpr double moving_area_change = 0.005;

// present, centroid, area and bounding box of a mask (CV_8U, non-zero = target); the other
// fields stay zero.
Truth truth_from_mask(const cv::Mat& mask);

// Whether a target seen in both frames moved between them (the rule of Truth::moving).
bool has_moved(const Truth& previous, const Truth& current);

}  // namespace raypoint::scene
