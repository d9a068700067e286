// SPDX-License-Identifier: MIT
#include "raypoint/view/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "labels.hpp"

namespace raypoint::view {
namespace {

constexpr int margin_left = 56;
constexpr int margin_right = 16;
constexpr int margin_top = 28;
constexpr int gap = 22;
constexpr int band_height = 24;
constexpr int axis_height = 34;  // time labels under the band

const cv::Scalar ink{40, 40, 40};
const cv::Scalar grid{225, 225, 225};

using detail::format_number;

void label(cv::Mat& image, const std::string& text, cv::Point at, const cv::Scalar& color) {
    detail::put_label(image, text, at, color, 0.42);
}

// One series as a polyline, broken wherever the track has no position.
template <typename Value, typename Row>
void draw_series(cv::Mat& image, const TrackLog& log, const PlotLayout& layout, Value value,
                 Row row, const cv::Scalar& color) {
    std::vector<cv::Point> run;
    const auto flush = [&] {
        if (run.size() == 1) cv::circle(image, run.front(), 1, color, cv::FILLED);
        if (run.size() > 1) cv::polylines(image, run, false, color, 2, cv::LINE_8);
        run.clear();
    };
    for (const TrackSample& sample : log.samples) {
        if (!sample.has_position) {
            flush();
            continue;
        }
        run.emplace_back(layout.column(sample.t), row(value(sample)));
    }
    flush();
}

}  // namespace

cv::Scalar state_color(core::TrackerState state) noexcept {
    switch (state) {
        case core::TrackerState::initializing:
            return {190, 190, 190};  // grey
        case core::TrackerState::searching:
            return {0, 215, 255};  // yellow
        case core::TrackerState::tracking:
            return {60, 180, 75};  // green
        case core::TrackerState::validating:
            return {200, 130, 0};  // blue
        case core::TrackerState::recovering:
            return {180, 50, 230};  // magenta
    }
    return {0, 0, 0};
}

int PlotLayout::column(double t) const noexcept {
    const double span = std::max(t_end - t_begin, 1e-9);
    // Inside the panel's frame: its border never covers a value.
    return xy_panel.x + 1 + cvRound((t - t_begin) / span * (xy_panel.width - 3));
}

int PlotLayout::xy_row(double fraction) const noexcept {
    const double clamped = std::clamp(fraction, 0.0, 1.0);
    return xy_panel.y + 1 + cvRound((1.0 - clamped) * (xy_panel.height - 3));
}

int PlotLayout::z_row(double z) const noexcept {
    const double clamped = std::clamp(z, z_low, z_high);
    return z_panel.y + 1 + cvRound((z_high - clamped) / (z_high - z_low) * (z_panel.height - 3));
}

PlotLayout plot_layout(const TrackLog& log, cv::Size size) {
    PlotLayout layout;
    layout.size = size;
    const int width = size.width - margin_left - margin_right;
    const int panels = size.height - margin_top - 2 * gap - band_height - axis_height;
    const int xy_height = panels * 3 / 5;
    layout.xy_panel = {margin_left, margin_top, width, xy_height};
    layout.z_panel = {margin_left, margin_top + xy_height + gap, width, panels - xy_height};
    layout.state_band = {margin_left, layout.z_panel.br().y + gap, width, band_height};
    if (!log.samples.empty()) {
        layout.t_begin = log.samples.front().t;
        layout.t_end = std::max(log.samples.back().t, layout.t_begin + 1e-3);
    }
    double z_extent = 0.05;
    for (const TrackSample& sample : log.samples) {
        if (sample.has_position) z_extent = std::max(z_extent, std::abs(sample.position.z));
    }
    z_extent *= 1.1;
    layout.z_low = -z_extent;
    layout.z_high = z_extent;
    return layout;
}

cv::Mat draw_plot(const TrackLog& log, const PlotLayout& layout) {
    cv::Mat image(layout.size, CV_8UC3, cv::Scalar(255, 255, 255));
    // Grid and frames first, so the curves draw over them.
    for (const double v : {0.25, 0.5, 0.75}) {
        const int row = layout.xy_row(v);
        cv::line(image, {layout.xy_panel.x, row}, {layout.xy_panel.br().x - 1, row}, grid);
    }
    const int zero = layout.z_row(0.0);
    cv::line(image, {layout.z_panel.x, zero}, {layout.z_panel.br().x - 1, zero}, grid);
    const double span = layout.t_end - layout.t_begin;
    const double step = span > 60 ? 10.0 : span > 20 ? 5.0 : span > 6 ? 1.0 : 0.5;
    for (double t = std::ceil(layout.t_begin / step) * step; t <= layout.t_end + 1e-9; t += step) {
        const int column = layout.column(t);
        for (const cv::Rect& panel : {layout.xy_panel, layout.z_panel}) {
            cv::line(image, {column, panel.y}, {column, panel.br().y - 1}, grid);
        }
        label(image, format_number(step < 1 ? "%.1f" : "%.0f", t),
              {column - 8, layout.state_band.br().y + 16}, ink);
    }
    label(image, "t (s)", {layout.state_band.br().x - 30, layout.state_band.br().y + 30}, ink);

    // The band: each frame's state from its time to the next frame's.
    for (std::size_t i = 0; i < log.samples.size(); ++i) {
        const int from = layout.column(log.samples[i].t);
        const int to = i + 1 < log.samples.size() ? layout.column(log.samples[i + 1].t)
                                                  : layout.state_band.br().x - 2;
        cv::rectangle(image, {from, layout.state_band.y},
                      {std::max(from, to), layout.state_band.br().y - 1},
                      state_color(log.samples[i].state), cv::FILLED);
    }

    // Clicks across both panels, under the curves.
    for (const ClickMark& click : log.clicks) {
        const int column = layout.column(click.t);
        const cv::Scalar& color = click.press ? plot_press_color : plot_release_color;
        cv::line(image, {column, layout.xy_panel.y}, {column, layout.z_panel.br().y - 1}, color,
                 click.press ? 2 : 1);
    }

    draw_series(
        image, log, layout, [](const TrackSample& s) { return s.position.x; },
        [&](double v) { return layout.xy_row(v); }, plot_x_color);
    draw_series(
        image, log, layout, [](const TrackSample& s) { return s.position.y; },
        [&](double v) { return layout.xy_row(v); }, plot_y_color);
    draw_series(
        image, log, layout, [](const TrackSample& s) { return s.position.z; },
        [&](double v) { return layout.z_row(v); }, plot_z_color);

    for (const cv::Rect& panel : {layout.xy_panel, layout.z_panel, layout.state_band}) {
        cv::rectangle(image, panel, ink);
    }
    label(image, "1", {layout.xy_panel.x - 14, layout.xy_row(1.0) + 5}, ink);
    label(image, "0", {layout.xy_panel.x - 14, layout.xy_row(0.0) + 5}, ink);
    label(image, format_number("%+.2f", layout.z_high), {4, layout.z_row(layout.z_high) + 10}, ink);
    label(image, format_number("%+.2f", layout.z_low), {4, layout.z_row(layout.z_low)}, ink);
    label(image, "state", {6, layout.state_band.y + 16}, ink);

    // Legend on top.
    int x = layout.xy_panel.x;
    const auto legend = [&](const std::string& text, const cv::Scalar& color) {
        cv::rectangle(image, {x, 10}, {x + 14, 20}, color, cv::FILLED);
        label(image, text, {x + 18, 20}, ink);
        x += 26 + static_cast<int>(text.size()) * 8;
    };
    legend("x", plot_x_color);
    legend("y", plot_y_color);
    legend("z", plot_z_color);
    legend("press", plot_press_color);
    legend("release", plot_release_color);
    for (const core::TrackerState state :
         {core::TrackerState::initializing, core::TrackerState::searching,
          core::TrackerState::tracking, core::TrackerState::validating,
          core::TrackerState::recovering}) {
        legend(std::string(core::to_string(state)), state_color(state));
    }
    return image;
}

}  // namespace raypoint::view
