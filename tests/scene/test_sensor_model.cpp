// SPDX-License-Identifier: MIT
// The renderer's sensor model: what a cheap webcam's rolling shutter and automatic controls do to
// the picture (mains flicker bands, exposure and white-balance drift, the shutter's skew).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/scene/renderer.hpp"
#include "renderer_testing.hpp"

namespace {

using namespace raypoint::scene;
using raypoint::scene::render_testing::mean_grey;
using raypoint::scene::render_testing::still;

// Mains flicker through a rolling shutter: horizontal bands whose rows differ from frame to
// frame by up to twice the depth, and that move between frames; none without flicker.
TEST(SceneRenderer, FlickerRollsHorizontalBandsThroughAStillScene) {
    SceneSpec s;
    s.empty_seconds = 10;  // no target, just the board
    s.seconds = 1;
    s.noise_sigma = 0;
    const auto row_ratio_spread = [](const SceneSpec& spec) {
        const Renderer r(spec);
        const cv::Mat a = r.render(10).bgr;
        const cv::Mat b = r.render(11).bgr;
        double lowest = 1e9;
        double highest = 0;
        for (int y = 0; y < spec.height; y += 8) {
            const cv::Rect row(0, y, spec.width, 1);
            const double ratio = mean_grey(a, row) / mean_grey(b, row);
            lowest = std::min(lowest, ratio);
            highest = std::max(highest, ratio);
        }
        return highest - lowest;
    };
    EXPECT_LT(row_ratio_spread(s), 0.01);
    s.flicker_depth = 0.12;
    EXPECT_GT(row_ratio_spread(s), 0.1);
    EXPECT_LT(row_ratio_spread(s), 0.5);
}

// Exposure and white-balance drift: slow (two frames apart alike), but over a quarter period
// the channels' balance moves.
TEST(SceneRenderer, DriftChangesGainAndBalanceSlowly) {
    SceneSpec s;
    s.empty_seconds = 10;
    s.seconds = 2;
    s.noise_sigma = 0;
    s.exposure_drift = 0.2;
    s.white_balance_drift = 0.1;
    s.drift_period = 4;
    const Renderer r(s);
    const auto blue_over_red = [&](int index) {
        const cv::Scalar m = cv::mean(r.render(index).bgr);
        return m[0] / m[2];
    };
    EXPECT_NEAR(blue_over_red(0), blue_over_red(1), 0.01);
    EXPECT_GT(std::abs(blue_over_red(30) - blue_over_red(0)), 0.05);  // 1 s = a quarter period
}

// Mean column of the mask's pixels in rows [top, bottom).
double mean_column(const cv::Mat& mask, int top, int bottom) {
    double sum = 0, count = 0;
    for (int y = top; y < bottom; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            if (!mask.at<std::uint8_t>(y, x)) continue;
            sum += x;
            count += 1;
        }
    }
    return count > 0 ? sum / count : -1;
}

TEST(SceneRenderer, RollingShutterShearsATargetMovingSideways) {
    SceneSpec moving = still(Target::sphere, 0.6, 0.3);
    moving.path.push_back({1.0, 0.7, 0.5, 0.6});  // about 256 px/s to the right
    moving.blur = 0;
    moving.readout_seconds = 0.1;  // slow, so that the shear is many pixels
    SceneSpec shuttered = moving;
    shuttered.rolling_shutter = true;
    const RenderedFrame global = Renderer(moving).render(15);
    const RenderedFrame rolling = Renderer(shuttered).render(15);
    const cv::Rect box = cv::boundingRect(rolling.mask);
    const int quarter = box.height / 4;
    // Rows read later show the target further right: the bottom quarter's middle is right of
    // the top quarter's by the travel over the rows' readout (~ 256 px/s x 0.1 s x 0.5).
    const double shear = mean_column(rolling.mask, box.br().y - quarter, box.br().y) -
                         mean_column(rolling.mask, box.y, box.y + quarter);
    EXPECT_GT(shear, 5.0);
    const cv::Rect still_box = cv::boundingRect(global.mask);
    const int still_quarter = still_box.height / 4;
    EXPECT_NEAR(mean_column(global.mask, still_box.br().y - still_quarter, still_box.br().y),
                mean_column(global.mask, still_box.y, still_box.y + still_quarter), 0.5);
    // The truth is the sheared mask, as the picture shows it.
    EXPECT_EQ(cv::countNonZero(rolling.mask != 0),
              cvRound(rolling.truth.area * static_cast<double>(rolling.mask.total())));
    EXPECT_NEAR(rolling.truth.area, global.truth.area, 0.02 * global.truth.area);
}

}  // namespace
