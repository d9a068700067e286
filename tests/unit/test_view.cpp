// SPDX-License-Identifier: MIT
// The pictures of daemon/view: the plot puts each series, the state band and the clicks where
// its layout says, and the preview's state text is told apart from every other state's.

#include <array>
#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "raypoint/config/schema.hpp"
#include "raypoint/view/plot.hpp"
#include "raypoint/view/preview_session.hpp"
#include "raypoint/view/setup_measure.hpp"

namespace raypoint::view {
namespace {

cv::Vec3b bgr(const cv::Scalar& s) {
    return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

// Rows of `column` within `panel` that have `color`.
std::vector<int> rows_with(const cv::Mat& image, int column, const cv::Rect& panel,
                           const cv::Scalar& color) {
    std::vector<int> rows;
    for (int y = panel.y; y < panel.br().y; ++y) {
        if (image.at<cv::Vec3b>(y, column) == bgr(color)) rows.push_back(y);
    }
    return rows;
}

// 4 s at 30 fps: searching for 1 s, then x rising 0.6 -> 0.9, y at 0.2, z a sine; a press at
// 2 s, a release at 2.5 s.
TrackLog known_track() {
    TrackLog log;
    for (int i = 0; i < 120; ++i) {
        TrackSample s;
        s.t = i / 30.0;
        s.state = s.t < 1.0 ? core::TrackerState::searching : core::TrackerState::tracking;
        s.has_position = s.t >= 1.0;
        s.position = {0.6 + 0.1 * (s.t - 1.0), 0.2, 0.08 * std::sin(s.t * 3.0)};
        log.samples.push_back(s);
    }
    log.clicks = {{2.0, true}, {2.5, false}};
    return log;
}

TEST(Plot, EachSeriesIsDrawnWhereItsValueIsAndNowhereElse) {
    const TrackLog log = known_track();
    const PlotLayout layout = plot_layout(log);
    const cv::Mat image = draw_plot(log, layout);
    ASSERT_EQ(image.size(), layout.size);
    for (const TrackSample& s : log.samples) {
        if (!s.has_position || s.t > 3.9) continue;
        const int column = layout.column(s.t);
        for (const auto& [value, row, panel, color] :
             {std::tuple{s.position.x, layout.xy_row(s.position.x), layout.xy_panel, plot_x_color},
              std::tuple{s.position.y, layout.xy_row(s.position.y), layout.xy_panel, plot_y_color},
              std::tuple{s.position.z, layout.z_row(s.position.z), layout.z_panel, plot_z_color}}) {
            const auto rows = rows_with(image, column, panel, color);
            ASSERT_FALSE(rows.empty()) << "t " << s.t << " value " << value;
            for (const int y : rows)
                EXPECT_NEAR(y, row, 3) << "t " << s.t << " value " << value;
        }
    }
    // No position while searching: no curve there.
    const int searching = layout.column(0.5);
    EXPECT_TRUE(rows_with(image, searching, layout.xy_panel, plot_x_color).empty());
    EXPECT_TRUE(rows_with(image, searching, layout.z_panel, plot_z_color).empty());
}

TEST(Plot, TheStateBandAndTheClicksAreColouredByTime) {
    const TrackLog log = known_track();
    const PlotLayout layout = plot_layout(log);
    const cv::Mat image = draw_plot(log, layout);
    const int band_row = layout.state_band.y + layout.state_band.height / 2;
    EXPECT_EQ(image.at<cv::Vec3b>(band_row, layout.column(0.5)),
              bgr(state_color(core::TrackerState::searching)));
    EXPECT_EQ(image.at<cv::Vec3b>(band_row, layout.column(3.0)),
              bgr(state_color(core::TrackerState::tracking)));
    // The press's line runs through both panels (away from the curves).
    const int press = layout.column(2.0);
    EXPECT_EQ(image.at<cv::Vec3b>(layout.xy_row(0.45), press), bgr(plot_press_color));
    EXPECT_EQ(image.at<cv::Vec3b>(layout.z_panel.y + 2, press), bgr(plot_press_color));
    EXPECT_EQ(image.at<cv::Vec3b>(layout.xy_row(0.45), layout.column(2.5)),
              bgr(plot_release_color));
    EXPECT_NE(image.at<cv::Vec3b>(layout.xy_row(0.45), layout.column(3.0)), bgr(plot_press_color));
}

TEST(PreviewStatus, StateTextMatchesOnlyItsOwnState) {
    const int rows = 120;
    const std::array states{core::TrackerState::initializing, core::TrackerState::searching,
                            core::TrackerState::tracking, core::TrackerState::validating,
                            core::TrackerState::recovering};
    for (const auto drawn : states) {
        cv::Mat picture(rows + status_panel_height, 320, CV_8UC3, cv::Scalar(32, 32, 32));
        draw_state_text(picture, state_text_origin(rows), drawn);
        for (const auto asked : states) {
            const double match = state_text_match(picture, rows, asked);
            if (asked == drawn) {
                EXPECT_GT(match, 0.99) << core::to_string(drawn);
            } else {
                EXPECT_LT(match, 0.5)
                    << core::to_string(drawn) << " read as " << core::to_string(asked);
            }
        }
    }
}

// 30 fps: 2 s still at x 0.3, 3 s moving to x 0.7 and back, then two pushes (sqrt(area) up
// 30% over 0.3 s, held 0.2 s, back over 0.3 s) 1.5 s apart; area 0.04 at rest.
TEST(SetupMeasure, FindsTheHandsRangeAndEachPushsDepth) {
    SetupMeasure measure;
    const double rest = 0.2;  // sqrt(0.04)
    for (int i = 0; i < 300; ++i) {
        const double t = i / 30.0;
        core::FrameResult r;
        r.timestamp = core::seconds_to_us(t);
        r.state = core::TrackerState::tracking;
        r.has_target = true;
        const double sweep = t < 2.0 ? 0.0 : t < 5.0 ? std::sin((t - 2.0) / 3.0 * CV_PI) : 0.0;
        r.centroid = {0.3 + 0.4 * sweep, 0.5};
        double scale = rest;
        for (const double start : {6.0, 7.5}) {
            const double u = t - start;
            if (u >= 0 && u < 0.3) scale = rest * (1.0 + 0.3 * u / 0.3);
            if (u >= 0.3 && u < 0.5) scale = rest * 1.3;
            if (u >= 0.5 && u < 0.8) scale = rest * (1.0 + 0.3 * (0.8 - u) / 0.3);
        }
        r.area = scale * scale;
        measure.add(r);
    }
    const SetupFigures f = measure.figures();
    EXPECT_EQ(f.tracked_frames, 300);
    EXPECT_NEAR(f.hand_area, 0.04, 1e-6);
    EXPECT_NEAR(f.left, 0.3, 0.01);
    EXPECT_NEAR(f.right, 0.7, 0.02);
    ASSERT_EQ(f.push_rises.size(), 2U);
    EXPECT_NEAR(f.push_depth, 0.3, 0.01);
    const auto proposal = measure.propose(config::Config{}, 1920);
    ASSERT_TRUE(proposal.has_value());
    const core::PointerSettings& p = proposal->config.core.pointer;
    EXPECT_NEAR(p.click.press_rise, 0.18, 1e-9);  // 0.6 of the depth
    EXPECT_NEAR(p.click.release_rise, 0.09, 1e-9);
    EXPECT_NEAR(p.motion.gain, 1920 / (f.right - f.left), 1.0);
    EXPECT_NEAR(p.motion.active_left, 0.28, 0.011);
    EXPECT_TRUE(config::cross_check(proposal->config).empty());
}

TEST(SetupMeasure, ProposesNothingFromTooFewTrackedFrames) {
    SetupMeasure measure;
    core::FrameResult r;
    r.state = core::TrackerState::tracking;
    r.area = 0.04;
    for (int i = 0; i < 10; ++i) {
        r.timestamp = core::seconds_to_us(i / 30.0);
        measure.add(r);
    }
    EXPECT_FALSE(measure.propose(config::Config{}, 1920).has_value());
}

}  // namespace
}  // namespace raypoint::view
