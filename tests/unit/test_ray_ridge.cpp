// SPDX-License-Identifier: MIT
// A ray's length runs to the ridge of the edge band in front of it, where the outline is:
// the strongest edge pixel, or the middle of a run of equally strong ones (a saturated band).

#include <gtest/gtest.h>

#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/ray_caster.hpp"

namespace {

using raypoint::core::RayCaster;
using raypoint::core::RayHit;

// A vertical band starting at column 30 with the given strengths, left to right; rays cast
// from (10, 20) with 4 rays: ray 0 points right (+x).
RayHit cast_right_into(const std::vector<int>& band) {
    cv::Mat edges = cv::Mat::zeros(40, 60, CV_8U);
    for (std::size_t i = 0; i < band.size(); ++i) {
        edges.col(30 + static_cast<int>(i)).setTo(band[i]);
    }
    std::vector<RayHit> hits;
    RayCaster(4).cast(edges, {10.0F, 20.0F}, hits);
    return hits[0];
}

TEST(RayRidge, RisingBandEndsAtItsStrongestPixel) {
    const RayHit hit = cast_right_into({100, 150, 200, 150, 100});
    EXPECT_EQ(hit.point, cv::Point2f(29.0F, 20.0F));  // the last pixel before the band
    EXPECT_FLOAT_EQ(hit.length, 22.0F);               // column 32: the 200
}

TEST(RayRidge, SaturatedPlateauEndsInItsMiddle) {
    const RayHit hit = cast_right_into({255, 255, 255});
    EXPECT_FLOAT_EQ(hit.length, 21.0F);  // columns 30..32: the middle is 31
}

TEST(RayRidge, ThinOutlineIsTheOutline) {
    const RayHit hit = cast_right_into({1});
    EXPECT_FLOAT_EQ(hit.length, 20.0F);
}

TEST(RayRidge, RayLeavingTheImageEndsAtTheBorder) {
    std::vector<RayHit> hits;
    RayCaster(4).cast(cv::Mat::zeros(40, 60, CV_8U), {10.0F, 20.0F}, hits);
    EXPECT_EQ(hits[0].point, cv::Point2f(59.0F, 20.0F));
    EXPECT_FLOAT_EQ(hits[0].length, 49.0F);
}

}  // namespace
