// SPDX-License-Identifier: MIT
#pragma once
// Paint primitives for the procedural room: colours and textured, shaded surfaces on an
// 8-bit BGR canvas.

#include <opencv2/core.hpp>

#include "rng.hpp"

namespace raypoint::scene::paint {

// hue in degrees, saturation and value 0..1.
cv::Scalar hsv(double hue, double saturation, double value);
cv::Scalar wall_colour(Rng& rng);
cv::Scalar wood_colour(Rng& rng);
cv::Scalar vivid_colour(Rng& rng);  // saturated, any brightness: books, posters, toys
cv::Scalar any_colour(Rng& rng);    // vivid, muted or dark
cv::Scalar scaled(const cv::Scalar& colour, double factor);

enum class Texture { flat, stripes, checker, fabric, grain };
Texture any_texture(Rng& rng);

// Fills rect with colour: lighter at the top (light from the ceiling), the texture's pattern,
// and a darker outline `edge` pixels wide (0 = none).
void surface(cv::Mat& canvas, cv::Rect rect, const cv::Scalar& colour, Texture texture, Rng& rng,
             int edge);

// A ceiling lamp somewhere above the frame on a CV_32FC3 image: each pixel times
// base + boost x exp(-d^2 / reach^2), d its distance from the lamp, reach 1.2 frame heights.
void ceiling_light(cv::Mat& light, Rng& rng, double base, double boost);

// A filled ellipse, anti-aliased, with a lighter upper left as if lit from above.
void blob(cv::Mat& canvas, cv::Point centre, cv::Size axes, const cv::Scalar& colour);

}  // namespace raypoint::scene::paint
