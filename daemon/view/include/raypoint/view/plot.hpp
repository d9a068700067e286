// SPDX-License-Identifier: MIT
#pragma once
// `raypoint plot`: a track's x, y and z over time, the tracker's state as a band of colours
// under them and the clicks as vertical lines, drawn with OpenCV into one picture.

#include <opencv2/core.hpp>

#include "raypoint/core/tracker_state.hpp"
#include "raypoint/view/track_log.hpp"

namespace raypoint::view {

// Pure BGR colours, so that a test (and a reader) can tell each series apart by its pixels.
inline const cv::Scalar plot_x_color{0, 0, 230};        // red
inline const cv::Scalar plot_y_color{0, 170, 0};        // green
inline const cv::Scalar plot_z_color{220, 0, 0};        // blue
inline const cv::Scalar plot_press_color{0, 140, 255};  // orange
inline const cv::Scalar plot_release_color{160, 160, 160};

// The state band's colours, also the preview's state text colour.
cv::Scalar state_color(core::TrackerState state) noexcept;

// Where things go in the picture: the drawing and the tests use the same mapping.
struct PlotLayout {
    cv::Size size{960, 560};
    cv::Rect xy_panel;    // x and y, 0..1 bottom to top
    cv::Rect z_panel;     // z, z_low..z_high bottom to top
    cv::Rect state_band;  // one colour a frame
    double t_begin = 0.0;
    double t_end = 1.0;
    double z_low = -0.1;
    double z_high = 0.1;

    int column(double t) const noexcept;
    int xy_row(double fraction) const noexcept;
    int z_row(double z) const noexcept;
};

// The layout for a track: its time span, z's range (symmetric around 0, at least +-0.05).
PlotLayout plot_layout(const TrackLog& log, cv::Size size = {960, 560});

// The picture, BGR.
cv::Mat draw_plot(const TrackLog& log, const PlotLayout& layout);

}  // namespace raypoint::view
