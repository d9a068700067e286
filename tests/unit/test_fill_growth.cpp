// SPDX-License-Identifier: MIT
// EstimatorSettings::fill_growth: a refined fill that grows past fill_growth times the last
// frame's fill of the same target has leaked, and is redone within the blocks the rays selected;
// forget_target() starts a new target without that memory, and restore() puts it back after a
// look at another region.

#include <memory>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/estimator.hpp"

namespace raypoint::core {
namespace {

const cv::Scalar edge(200);

// 160x120: a disk (radius 15, 2 px outline) around (60, 60).
cv::Mat disk() {
    cv::Mat edges(120, 160, CV_8U, cv::Scalar(0));
    cv::circle(edges, {60, 60}, 15, edge, 2);
    return edges;
}

// The same disk a frame later, its outline open on the right into a chamber the rays run into,
// and from the chamber a corridor down to the bottom border that no ray reaches. The whole is
// within fill_limit of the blocks the rays select; it is 2.4 times the disk.
cv::Mat leaking_disk() {
    cv::Mat edges = disk();
    cv::rectangle(edges, cv::Rect(74, 48, 22, 24), edge, 2);
    cv::line(edges, {84, 70}, {84, 119}, edge, 2);
    cv::line(edges, {95, 70}, {95, 119}, edge, 2);
    edges(cv::Rect(86, 68, 8, 6)).setTo(0);   // the chamber open into the corridor
    edges(cv::Rect(72, 55, 6, 10)).setTo(0);  // the gap in the disk's outline
    return edges;
}

std::unique_ptr<Estimator> estimator(double growth) {
    EstimatorSettings settings;
    settings.fill_growth = growth;
    settings.extremity = 0.0;
    return make_estimator(settings);
}

TEST(FillGrowth, ALeakPastTheGrowthIsCutToTheSelectedBlocks) {
    const cv::Mat before = disk();
    const cv::Mat after = leaking_disk();
    const auto unchecked = estimator(0.0);
    const auto checked = estimator(1.75);
    const Estimate first = checked->estimate(before, {60, 60});
    EXPECT_DOUBLE_EQ(first.area, unchecked->estimate(before, {60, 60}).area);
    const Estimate leaked = unchecked->estimate(after, {60, 60});
    const Estimate cut = checked->estimate(after, {60, 60});
    ASSERT_GT(leaked.area, 2.0 * first.area);
    EXPECT_LT(cut.area, leaked.area - 50.0);       // the corridor's bottom is gone
    EXPECT_LT(cut.centroid.y, leaked.centroid.y);  // and its pull down
}

TEST(FillGrowth, ANewTargetHasNoLastFill) {
    const auto checked = estimator(1.75);
    checked->estimate(disk(), {60, 60});
    checked->forget_target();
    const Estimate fresh = checked->estimate(leaking_disk(), {60, 60});
    EXPECT_DOUBLE_EQ(fresh.area, estimator(0.0)->estimate(leaking_disk(), {60, 60}).area);
}

// A look at another, larger region (a possible switch of target) is put back: the target's next
// leak is cut as if the look had not happened. Without the restore the larger fill lets it by.
TEST(FillGrowth, ALookElsewhereLeavesTheTargetsLastFill) {
    cv::Mat both = disk();
    cv::rectangle(both, cv::Rect(100, 10, 50, 100), edge, 2);  // 2.4x the leak's area
    const auto restored = estimator(1.75);
    const auto forgotten = estimator(1.75);
    restored->estimate(disk(), {60, 60});
    forgotten->estimate(disk(), {60, 60});
    const Estimator::Memory memory = restored->memory();
    EXPECT_GT(memory, 0U);
    restored->estimate(both, {125, 60});
    forgotten->estimate(both, {125, 60});
    EXPECT_GT(restored->memory(), memory);
    restored->restore(memory);
    EXPECT_EQ(restored->memory(), memory);
    const Estimate cut = restored->estimate(leaking_disk(), {60, 60});
    const Estimate leaked = forgotten->estimate(leaking_disk(), {60, 60});
    EXPECT_LT(cut.area, leaked.area - 50.0);
    EXPECT_DOUBLE_EQ(cut.area, [] {
        const auto fresh = estimator(1.75);
        fresh->estimate(disk(), {60, 60});
        return fresh->estimate(leaking_disk(), {60, 60}).area;
    }());
}

}  // namespace
}  // namespace raypoint::core
