// SPDX-License-Identifier: MIT
#pragma once
// A target's look in its own frame: a signed distance field of its outline and its colour,
// sampled on a texture that the renderer warps to each pose. Sampling the distance (not
// coverage) keeps outlines sharp and exact at any scale: the mask is where it is <= 0.

#include <memory>

#include <opencv2/core.hpp>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

// Target units: 1 unit = the target's size (sphere diameter, hand height); x right, y down,
// origin at the target's centre.
struct Sprite {
    cv::Mat sdf;     // CV_32F, signed distance to the outline in units, negative inside
    cv::Mat colour;  // CV_32FC3, BGR 0..255 at full light, continued beyond the outline
    double texels_per_unit = 0;
    cv::Point2d origin;  // texel coordinates of the centre (texel k spans [k, k + 1))
    cv::Rect2d extent;   // the outline's bounding box in units
    double area = 0;     // the outline's area in square units
    bool rotates = false;
    // The hand's wrist: the centre of its lower end and its half width, in units (0 for the
    // sphere). A forearm continues from there along +y.
    cv::Point2d wrist;
    double wrist_radius = 0;
};

// spread: the hand's fingers fanned (1), side by side (0), curled into a fist (-1), and between;
// the sphere has none.
Sprite make_sprite(Target target, const Colour& colour, double spread = 1.0);

// make_sprite, remembered: renderers of the same target, colour and spread share one sprite
// (tests build many renderers, and a hand's texture takes ~10 ms). Thread-safe.
std::shared_ptr<const Sprite> shared_sprite(Target target, const Colour& colour,
                                            double spread = 1.0);

// A hand whose fingers move is drawn at the nearest of 2 spread_levels + 1 spreads from -1 to 1.
constexpr int spread_levels = 16;

Colour default_colour(Target target, Background background);

}  // namespace raypoint::scene
