// SPDX-License-Identifier: MIT
#pragma once
// Drawn edge images for the estimator tests: a filled mask, its outline and the fair truth.

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace raypoint::test {

// The outline is the mask's 3x3 morphological gradient: a band 2 px wide, one layer inside the
// mask and one outside, like the Sobel band of a step (which straddles it). The fair area is
// the pixels strictly inside the band plus half the band (the outline runs through its
// middle); it comes within a fraction of a percent of the mask's own pixel count.
struct Shape {
    cv::Mat mask;   // CV_8U 0/1
    cv::Mat edges;  // CV_8U 0/1
    double area = 0.0;
    cv::Point2d centroid;  // of the mask
};

inline Shape outline(const cv::Mat& mask) {
    Shape shape;
    shape.mask = mask;
    cv::morphologyEx(mask, shape.edges, cv::MORPH_GRADIENT,
                     cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
    const cv::Mat inside = mask & (shape.edges == 0);
    shape.area = cv::countNonZero(inside) + 0.5 * cv::countNonZero(shape.edges);
    const cv::Moments m = cv::moments(mask, true);
    shape.centroid = {m.m10 / m.m00, m.m01 / m.m00};
    return shape;
}

// A disk of radius 20 centred at (80, 60) in 160x120: 1257 mask pixels, 1101 inside the band,
// 324 in it; fair area 1101 + 162 = 1263.
inline Shape disk() {
    cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::circle(mask, {80, 60}, 20, 1, cv::FILLED);
    return outline(mask);
}

// A hand: palm ellipse (axes 20 x 24 at (80, 80)) and five fingers 7 px wide, spread at -150
// (thumb), -115, -90, -65 and -30 degrees; 2373 mask pixels, 12% of the frame, non-convex.
struct Hand {
    Shape shape;
    cv::Point2f palm{80.0F, 80.0F};
    std::vector<cv::Point2f> fingertips;  // 4 px in from each fingertip, on the finger's axis
};

inline Hand hand() {
    Hand hand;
    cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
    cv::ellipse(mask, {80, 80}, {20, 24}, 0, 0, 360, 1, cv::FILLED);
    const double angles[5] = {-150, -115, -90, -65, -30};
    const double lengths[5] = {20, 28, 30, 28, 22};
    for (int i = 0; i < 5; ++i) {
        const double a = angles[i] * M_PI / 180.0;
        const cv::Point2d d(std::cos(a), std::sin(a));
        const cv::Point2d n(-d.y, d.x);
        const cv::Point2d base = cv::Point2d(80, 80) + d * 16.0;
        const cv::Point2d tip = base + d * lengths[i];
        const std::vector<cv::Point> finger{base + n * 3.5, tip + n * 3.5, tip - n * 3.5,
                                            base - n * 3.5};
        cv::fillConvexPoly(mask, finger, 1);
        const cv::Point2d inner = base + d * (lengths[i] - 4.0);
        hand.fingertips.emplace_back(static_cast<float>(std::round(inner.x)),
                                     static_cast<float>(std::round(inner.y)));
    }
    hand.shape = outline(mask);
    return hand;
}

}  // namespace raypoint::test
