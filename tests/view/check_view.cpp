// SPDX-License-Identifier: MIT
// raypoint-check-view: checks the pictures raypoint draws against what they must show, for the
// CLI tests (tests/cli/test_preview_cli.sh). Exit 0 when the picture is right, 1 with the reason.
//   check-view screenshot SHOT.png CX CY STATE   the preview's centroid marker within 3 px of
//                                                (CX, CY) (fractions of the frame), and STATE's
//                                                name in the status panel
//   check-view plot PLOT.png TRACK.jsonl         x, y and z drawn where the track puts them

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include <opencv2/imgcodecs.hpp>

#include "raypoint/view/plot.hpp"
#include "raypoint/view/preview_session.hpp"

namespace {

using namespace raypoint;

int check_screenshot(const cv::Mat& shot, double cx, double cy, std::string_view state_name) {
    const int rows = shot.rows - view::status_panel_height;
    const cv::Scalar& c = view::overlay_centroid_color;
    const cv::Vec3b marker(static_cast<uchar>(c[0]), static_cast<uchar>(c[1]),
                           static_cast<uchar>(c[2]));
    double sx = 0, sy = 0;
    int count = 0;
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < shot.cols; ++x) {
            if (shot.at<cv::Vec3b>(y, x) != marker) continue;
            sx += x;
            sy += y;
            ++count;
        }
    }
    // A cross 18 pixels across and 2 thick has about 70 pixels.
    if (count < 30 || count > 120) {
        std::printf("FAIL: %d centroid-marker pixels (expected one cross of ~70)\n", count);
        return 1;
    }
    const double mx = sx / count + 0.5;  // pixel centres to fractions' coordinates
    const double my = sy / count + 0.5;
    const double error = std::hypot(mx - cx * shot.cols, my - cy * rows);
    std::printf("centroid marker at %.2f %.2f, truth %.2f %.2f: %.2f px off\n", mx, my,
                cx * shot.cols, cy * rows, error);
    if (error > 3.0) {
        std::printf("FAIL: the centroid marker is more than 3 px from the truth\n");
        return 1;
    }
    for (const auto state : {core::TrackerState::initializing, core::TrackerState::searching,
                             core::TrackerState::tracking, core::TrackerState::validating,
                             core::TrackerState::recovering}) {
        if (core::to_string(state) != state_name) continue;
        const double match = view::state_text_match(shot, rows, state);
        std::printf("state text '%s': match %.3f\n", std::string(state_name).c_str(), match);
        if (match < 0.9) {
            std::printf("FAIL: the state text is not '%s'\n", std::string(state_name).c_str());
            return 1;
        }
        return 0;
    }
    std::printf("FAIL: '%s' is no state\n", std::string(state_name).c_str());
    return 1;
}

// Every frame with a position: its column holds x, y and z's colours within 2 rows of where
// the values go (a curve crossing another may cover it: at most 5% of samples may miss).
int check_plot(const cv::Mat& plot, const std::string& track) {
    const view::TrackLog log = view::read_track_jsonl(track);
    const view::PlotLayout layout = view::plot_layout(log, plot.size());
    int checked = 0, missed = 0;
    const auto near = [&](int column, int row, const cv::Scalar& s) {
        const cv::Vec3b color(static_cast<uchar>(s[0]), static_cast<uchar>(s[1]),
                              static_cast<uchar>(s[2]));
        for (int y = row - 2; y <= row + 2; ++y) {
            if (y >= 0 && y < plot.rows && plot.at<cv::Vec3b>(y, column) == color) return true;
        }
        return false;
    };
    for (const view::TrackSample& sample : log.samples) {
        const int column = layout.column(sample.t);
        if (!sample.has_position) continue;
        checked += 3;
        const auto miss = [&](int row, const cv::Scalar& color, const char* name) {
            if (near(column, row, color)) return 0;
            std::printf("t %.3f: no %s at column %d row %d\n", sample.t, name, column, row);
            return 1;
        };
        missed += miss(layout.xy_row(sample.position.x), view::plot_x_color, "x");
        missed += miss(layout.xy_row(sample.position.y), view::plot_y_color, "y");
        missed += miss(layout.z_row(sample.position.z), view::plot_z_color, "z");
        const cv::Scalar band = view::state_color(sample.state);
        const cv::Vec3b b =
            plot.at<cv::Vec3b>(layout.state_band.y + layout.state_band.height / 2, column);
        checked += 1;
        if (b != cv::Vec3b(static_cast<uchar>(band[0]), static_cast<uchar>(band[1]),
                           static_cast<uchar>(band[2]))) {
            std::printf("t %.3f: the state band is not %s's colour\n", sample.t,
                        std::string(core::to_string(sample.state)).c_str());
            ++missed;
        }
    }
    std::printf("plot: %d of %d samples where the track puts them\n", checked - missed, checked);
    if (checked == 0 || missed > checked / 20) {
        std::printf("FAIL: the plot does not follow the track\n");
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string_view mode = argc > 1 ? argv[1] : "";
    const cv::Mat picture = argc > 2 ? cv::imread(argv[2], cv::IMREAD_COLOR) : cv::Mat();
    if (argc > 2 && picture.empty()) {
        std::printf("FAIL: cannot read %s\n", argv[2]);
        return 1;
    }
    if (mode == "screenshot" && argc == 6) {
        return check_screenshot(picture, std::atof(argv[3]), std::atof(argv[4]), argv[5]);
    }
    if (mode == "plot" && argc == 4) return check_plot(picture, argv[3]);
    std::fprintf(stderr,
                 "usage: raypoint-check-view screenshot SHOT.png CX CY STATE\n"
                 "       raypoint-check-view plot PLOT.png TRACK.jsonl\n");
    return 2;
}
