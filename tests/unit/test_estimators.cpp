// SPDX-License-Identifier: MIT
// The four object projection feature estimators (paper 3.1-3.4) on drawn edge images.
//
// What each measures (estimator_common.cpp, raster_estimator.cpp):
//  - ray, iterative-ray, iterative-ny-ray: area = the fan sum(L^2 / 2 * 2 pi / n) of rays that
//    stop on the last pixel before the edge, so the fan's rim runs through the centres of the
//    last inside pixels: it misses their outer half pixel and the inner half of the 2 px band,
//    about 1.5 px of radius. For the r = 20 disk, (18.5 / 20)^2 = 0.86: 14% short by geometry,
//    16-17% with 16 rays' discretisation. That is what the paper's ray areas are; the bound
//    asserted is [-18%, -12%], both sides, so a change either way shows.
//  - raster, refined: pixels reachable from the rays plus the edge band up to its ridge (flat
//    0/1 band here: every band pixel is a ridge pixel and counts half) = the fair truth.
//  - raster, blocks: whole 8x8 blocks the rays ran through (paper 3.4): an overestimate.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "raypoint/core/estimator.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/ray_caster.hpp"
#include "shapes.hpp"

namespace raypoint::core {
namespace {

std::unique_ptr<Estimator> make(EstimatorKind kind, AreaMode mode = AreaMode::refined) {
    EstimatorSettings settings;
    settings.kind = kind;
    settings.area_mode = mode;
    return make_estimator(settings);
}

double centroid_error(const Estimate& e, cv::Point2d truth) {
    return std::hypot(e.centroid.x - truth.x, e.centroid.y - truth.y);
}

double area_error(const Estimate& e, double truth) {
    return (e.area - truth) / truth;
}

bool inside(const test::Shape& shape, cv::Point2f p) {
    const cv::Point q(cvRound(p.x), cvRound(p.y));
    return shape.mask.at<std::uint8_t>(q) != 0 && shape.edges.at<std::uint8_t>(q) == 0;
}

constexpr EstimatorKind all_kinds[] = {EstimatorKind::ray, EstimatorKind::iterative_ray,
                                       EstimatorKind::iterative_ny_ray, EstimatorKind::raster};

TEST(EstimatorNames, RoundTripAndUnknownNames) {
    for (const EstimatorKind kind : all_kinds) {
        EstimatorKind parsed = EstimatorKind::ray;
        if (kind == EstimatorKind::ray) parsed = EstimatorKind::raster;
        ASSERT_TRUE(estimator_from_string(to_string(kind), parsed)) << to_string(kind);
        EXPECT_EQ(parsed, kind);
        EXPECT_NE(make(kind), nullptr);
    }
    EXPECT_EQ(to_string(EstimatorKind::iterative_ny_ray), "iterative-ny-ray");
    for (const char* wrong : {"", "rays", "Raster", "iterative_ray", "raster "}) {
        EstimatorKind kind = EstimatorKind::iterative_ray;
        EXPECT_FALSE(estimator_from_string(wrong, kind)) << wrong;
        EXPECT_EQ(kind, EstimatorKind::iterative_ray);  // untouched
    }
}

struct DiskCase {
    EstimatorKind kind;
    double centroid_tolerance_off_centre;
    double area_low;
    double area_high;
};

void PrintTo(const DiskCase& c, std::ostream* os) {
    *os << to_string(c.kind);
}

class Disk : public ::testing::TestWithParam<DiskCase> {};

TEST_P(Disk, CentroidAndAreaFromTheCentreAndOffCentre) {
    const DiskCase c = GetParam();
    const test::Shape disk = test::disk();
    ASSERT_NEAR(disk.area, 1263.0, 0.5);
    auto estimator = make(c.kind);
    for (const cv::Point2f start : {cv::Point2f(80.0F, 60.0F), cv::Point2f(70.0F, 55.0F)}) {
        SCOPED_TRACE(::testing::Message() << to_string(c.kind) << " from " << start);
        const Estimate e = estimator->estimate(disk.edges, start);
        const bool centred = start == cv::Point2f(80.0F, 60.0F);
        EXPECT_LE(centroid_error(e, disk.centroid),
                  centred ? 1.0 : c.centroid_tolerance_off_centre);
        EXPECT_GE(area_error(e, disk.area), c.area_low) << e.area;
        EXPECT_LE(area_error(e, disk.area), c.area_high) << e.area;
        EXPECT_TRUE(inside(disk, e.inner)) << e.inner;
        EXPECT_GE(e.iterations, 1);
    }
}

// Measured (centre / off-centre): ray centroid 0.00 / 5.58 px, area +0.9% / +0.3%;
// iterative-ray 0.00 / 0.31, +0.9%; iterative-ny-ray 0.00 / 0.10, -1.8%; raster 0.00 / 0.00,
// -0.8%. Ray lengths run to the outline's ridge; when they stopped at the last pixel inside,
// the ray estimators read the disk 16-17% small. One cast from (70, 55) is not centred (paper
// 3.1's drawback): its mean hit is 5.6 px toward the start, the tightest bound it meets is 6 px.
INSTANTIATE_TEST_SUITE_P(Kinds, Disk,
                         ::testing::Values(DiskCase{EstimatorKind::ray, 6.0, -0.05, 0.05},
                                           DiskCase{EstimatorKind::iterative_ray, 1.0, -0.05, 0.05},
                                           DiskCase{EstimatorKind::iterative_ny_ray, 1.0, -0.05,
                                                    0.05},
                                           DiskCase{EstimatorKind::raster, 1.0, -0.05, 0.05}),
                         [](const auto& test_info) {
                             std::string name(to_string(test_info.param.kind));
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(RasterBlocks, PaperAreaIsWholeBlocks) {
    // The paper's 8-rasterization: 26 blocks x 64 = 1664 for the disk, 32% over; the block
    // centroid is at most half a block's asymmetry off (measured 0.71 px).
    const test::Shape disk = test::disk();
    const Estimate e =
        make(EstimatorKind::raster, AreaMode::blocks)->estimate(disk.edges, {70, 55});
    EXPECT_EQ(std::fmod(e.area, 64.0), 0.0);
    EXPECT_GE(e.area, disk.area);
    EXPECT_LE(e.area, 1.4 * disk.area);
    EXPECT_LE(centroid_error(e, disk.centroid), 1.0);
}

TEST(Hand, RasterFromThePalmAndEveryFingertip) {
    const test::Hand hand = test::hand();
    const test::Shape& shape = hand.shape;
    auto raster = make(EstimatorKind::raster);
    std::vector<cv::Point2f> starts{hand.palm};
    starts.insert(starts.end(), hand.fingertips.begin(), hand.fingertips.end());
    for (const cv::Point2f start : starts) {
        SCOPED_TRACE(::testing::Message() << "from " << start);
        ASSERT_TRUE(inside(shape, start));
        const Estimate e = raster->estimate(shape.edges, start);
        // Measured: 0.01 px and -1.1% from every start; the inner point ends in the palm.
        EXPECT_LE(centroid_error(e, shape.centroid), 2.0);
        EXPECT_LE(std::abs(area_error(e, shape.area)), 0.10) << e.area;
        EXPECT_LT(std::hypot(e.inner.x - 80.0F, e.inner.y - 75.0F), 10.0) << e.inner;
    }
}

TEST(Hand, FromAFingertipRasterDoesBest) {
    // The paper's isolated-area case (3.1-3.4). Measured from the middle fingertip (80, 38):
    //   ray               centroid 27 px off, area -64% (sees the finger only)
    //   iterative-ray              4.0 px,        -20%
    //   iterative-ny-ray           4.1 px,        -40% (fans from hit points on the outline)
    //   raster                     0.01 px,       -1.1%
    const test::Hand hand = test::hand();
    const test::Shape& shape = hand.shape;
    for (const cv::Point2f tip : hand.fingertips) {
        SCOPED_TRACE(::testing::Message() << "from " << tip);
        std::vector<double> centroid;
        std::vector<double> area;
        for (const EstimatorKind kind : all_kinds) {
            const Estimate e = make(kind)->estimate(shape.edges, tip);
            centroid.push_back(centroid_error(e, shape.centroid));
            area.push_back(std::abs(area_error(e, shape.area)));
        }
        EXPECT_GT(centroid[0], 20.0);         // one cast stays in the finger
        EXPECT_LT(centroid[1], centroid[0]);  // iterating walks out of it (paper 3.2)
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_LT(centroid[3], centroid[k]) << to_string(all_kinds[k]);
            EXPECT_LT(area[3], area[k]) << to_string(all_kinds[k]);
        }
    }
}

TEST(RealEdges, RasterOnAPreprocessedDisk) {
    // A black disk of radius 80 on white, 640x480, through the default Preprocessor: a 20
    // working px disk with real Sobel edges. Its centre (321, 243) is at working
    // ((321 + 0.5) / 4 - 0.5, (243 + 0.5) / 4 - 0.5) = (79.875, 60.375); area pi 20^2 = 1256.6.
    cv::Mat frame;
    test::draw_disk_frame(frame, {321, 243}, 80);
    Preprocessor pre(PreprocessSettings{});
    ASSERT_TRUE(pre.process(test::bgr_view(frame)));
    const Estimate e = make(EstimatorKind::raster)->estimate(pre.edges(), {83.0F, 58.0F});
    EXPECT_LE(std::hypot(e.centroid.x - 79.875, e.centroid.y - 60.375), 0.5);
    // Measured -4.1% (-7.8% at radius 40 input px, -2.7% at 120).
    EXPECT_NEAR(e.area, 1256.6, 0.05 * 1256.6);
}

// A 1 px square outline x = 40..80, y = 30..70; inside, the rays from (60, 50) stop 19 px
// away along their major axis: at x = 41 or 79 or y = 31 or 69.
cv::Mat square_outline() {
    cv::Mat edges = cv::Mat::zeros(120, 160, CV_8U);
    cv::rectangle(edges, {40, 30}, {80, 70}, 1, 1);
    return edges;
}

TEST(RayCaster, RaysStopBeforeTheEdgeAndMeasureToIt) {
    const cv::Mat edges = square_outline();
    const RayCaster caster(16);
    ASSERT_EQ(caster.rays(), 16);
    std::vector<RayHit> hits;
    caster.cast(edges, {60.0F, 50.0F}, hits);
    ASSERT_EQ(hits.size(), 16U);
    for (int k = 0; k < 16; ++k) {
        const double angle = 2.0 * M_PI * k / 16;
        const double major = std::max(std::abs(std::cos(angle)), std::abs(std::sin(angle)));
        const RayHit& hit = hits[static_cast<std::size_t>(k)];
        SCOPED_TRACE(::testing::Message() << "ray " << k << " hit " << hit.point);
        const float dx = hit.point.x - 60.0F;
        const float dy = hit.point.y - 50.0F;
        EXPECT_NEAR(std::max(std::abs(dx), std::abs(dy)), 19.0F, 1e-4F);
        // The hit is the last pixel inside (19 steps); the length runs on to the outline (20).
        EXPECT_NEAR(hit.length, 20.0 / major, 1e-4);
        EXPECT_NEAR(std::atan2(dy, dx), std::atan2(std::sin(angle), std::cos(angle)), 1e-4);
        EXPECT_EQ(edges.at<std::uint8_t>(cvRound(hit.point.y), cvRound(hit.point.x)), 0);
    }
}

TEST(RayCaster, VisitsEveryPixelARunsThroughOriginIncluded) {
    const cv::Mat edges = square_outline();
    int visits = 0;
    bool on_edge = false;
    std::vector<RayHit> hits;
    RayCaster(4).cast(edges, {60.0F, 50.0F}, hits, [&](int x, int y) {
        ++visits;
        on_edge = on_edge || edges.at<std::uint8_t>(y, x) != 0;
    });
    EXPECT_EQ(visits, 1 + 4 * 19);
    EXPECT_FALSE(on_edge);
}

// An edge image whose rows are further apart than its width (a region of a larger image): the
// offset a visit may take is the pixel's byte offset, y * step + x, and the pixels are those a
// two-argument visit gets.
TEST(RayCaster, AnOffsetVisitGetsThePixelsByteOffset) {
    cv::Mat wide = cv::Mat::zeros(120, 200, CV_8U);
    const cv::Mat edges = wide(cv::Rect(20, 0, 160, 120));
    square_outline().copyTo(edges);
    ASSERT_GT(edges.step[0], static_cast<std::size_t>(edges.cols));
    std::vector<cv::Point> pixels;
    std::vector<cv::Point> offset_pixels;
    std::vector<RayHit> hits;
    RayCaster(16).cast(edges, {61.3F, 48.6F}, hits,
                       [&](int x, int y) { pixels.emplace_back(x, y); });
    std::vector<RayHit> offset_hits;
    RayCaster(16).cast(edges, {61.3F, 48.6F}, offset_hits, [&](int x, int y, std::size_t offset) {
        offset_pixels.emplace_back(x, y);
        EXPECT_EQ(offset, static_cast<std::size_t>(y) * edges.step[0] + x);
        EXPECT_EQ(edges.data[offset], 0);
    });
    EXPECT_EQ(offset_pixels, pixels);
    ASSERT_EQ(offset_hits.size(), hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        EXPECT_EQ(offset_hits[i].point, hits[i].point);
        EXPECT_EQ(offset_hits[i].length, hits[i].length);
    }
}

// The raster estimator marks the rays' pixels by their offset in the edge image: on a region of
// a larger image it estimates exactly what it does on a copy with rows one width apart.
TEST(RasterBlocks, ARegionOfALargerImageGivesTheSameEstimate) {
    const test::Hand hand = test::hand();
    cv::Mat wide = cv::Mat::zeros(hand.shape.edges.rows, hand.shape.edges.cols + 24, CV_8U);
    const cv::Mat region = wide(cv::Rect(8, 0, hand.shape.edges.cols, hand.shape.edges.rows));
    hand.shape.edges.copyTo(region);
    ASSERT_TRUE(hand.shape.edges.isContinuous());
    auto raster = make(EstimatorKind::raster);
    const Estimate continuous = raster->estimate(hand.shape.edges, hand.palm);
    const Estimate in_region = raster->estimate(region, hand.palm);
    const Estimate again = raster->estimate(hand.shape.edges, hand.palm);
    for (const Estimate& e : {in_region, again}) {
        EXPECT_EQ(e.centroid, continuous.centroid);
        EXPECT_EQ(e.area, continuous.area);
        EXPECT_EQ(e.inner, continuous.inner);
        EXPECT_EQ(e.iterations, continuous.iterations);
    }
}

TEST(RayCaster, OriginOnAnEdgeOrOutsideGivesZeroLengthRays) {
    const cv::Mat edges = square_outline();
    for (const cv::Point2f origin : {cv::Point2f(40.0F, 50.0F), cv::Point2f(-3.0F, 50.0F)}) {
        std::vector<RayHit> hits;
        int visits = 0;
        RayCaster(16).cast(edges, origin, hits, [&](int, int) { ++visits; });
        ASSERT_EQ(hits.size(), 16U);
        for (const RayHit& hit : hits) {
            EXPECT_EQ(hit.length, 0.0F);
            EXPECT_EQ(hit.point, origin);
        }
        EXPECT_EQ(visits, 0);
    }
}

TEST(RayCaster, WalkStopsBeforeAnEdgeOrReachesItsTarget) {
    const cv::Mat edges = square_outline();
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, {100, 50}), cv::Point2f(79, 50));
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, {80, 50}), cv::Point2f(79, 50));  // edge target
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, {60, 10}), cv::Point2f(60, 31));
    const cv::Point2f free_target(70.3F, 55.6F);
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, free_target), free_target);
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, {60.4F, 50.3F}), cv::Point2f(60.4F, 50.3F));
    EXPECT_EQ(RayCaster::walk(edges, {60, 50}, {200, 50}).x, 79.0F);  // past the image
}

TEST(RayCaster, WalkNeverEndsOnAnEdgeEvenForSubPixelMoves) {
    const cv::Mat edges = square_outline();
    const cv::Point2f end = RayCaster::walk(edges, {79.0F, 50.0F}, {79.6F, 50.0F});
    EXPECT_EQ(edges.at<std::uint8_t>(cvRound(end.y), cvRound(end.x)), 0) << end;
    EXPECT_EQ(end, cv::Point2f(79.0F, 50.0F));
}

TEST(RayCaster, OffEdgeMovesToTheNearestOpenPixel) {
    cv::Mat edges = square_outline();
    EXPECT_EQ(RayCaster::off_edge(edges, {60, 50}, 3), cv::Point2f(60, 50));  // already off
    const cv::Point2f moved = RayCaster::off_edge(edges, {40, 50}, 3);
    EXPECT_EQ(std::abs(moved.x - 40.0F) + std::abs(moved.y - 50.0F), 1.0F) << moved;
    EXPECT_EQ(edges.at<std::uint8_t>(cvRound(moved.y), cvRound(moved.x)), 0);
    EXPECT_EQ(RayCaster::off_edge(edges, {40, 50}, 0), cv::Point2f(40, 50));  // 0 = never
    cv::rectangle(edges, {10, 10}, {30, 30}, 1, cv::FILLED);  // 21 px thick: none within 3
    EXPECT_EQ(RayCaster::off_edge(edges, {20, 20}, 3), cv::Point2f(20, 20));
}

}  // namespace
}  // namespace raypoint::core
