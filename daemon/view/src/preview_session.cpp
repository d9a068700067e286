// SPDX-License-Identifier: MIT
#include "raypoint/view/preview_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "labels.hpp"
#include "raypoint/view/plot.hpp"

namespace raypoint::view {
namespace {

constexpr int state_font = cv::FONT_HERSHEY_SIMPLEX;
constexpr double state_scale = 0.7;
constexpr int state_thickness = 2;
const cv::Scalar panel_ink{235, 235, 235};
constexpr int min_picture_width = 560;  // the status lines' width
constexpr core::Timestamp recovery_hold_us = 500'000;

std::string upper(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) {
        return c == '-' ? ' ' : static_cast<char>(std::toupper(c));
    });
    return out;
}

using detail::format_number;

void text(cv::Mat& image, const std::string& line, cv::Point at, const cv::Scalar& color) {
    detail::put_label(image, line, at, color, 0.5);
}

// 0.05 per second of frames: a steady figure that still follows a change within a second.
double average(double previous, double value) {
    return previous == 0.0 ? value : 0.95 * previous + 0.05 * value;
}

}  // namespace

cv::Point state_text_origin(int frame_rows) noexcept {
    return {10, frame_rows + 26};
}

void draw_state_text(cv::Mat& image, cv::Point origin, core::TrackerState state) {
    cv::putText(image, upper(core::to_string(state)), origin, state_font, state_scale,
                state_color(state), state_thickness, cv::LINE_8);
}

double state_text_match(const cv::Mat& picture, int frame_rows, core::TrackerState state) {
    const cv::Point origin = state_text_origin(frame_rows);
    // The box every state's name fits in.
    const cv::Rect box =
        cv::Rect(origin.x - 2, origin.y - 22, 190, 30) & cv::Rect(0, 0, picture.cols, picture.rows);
    if (box.area() == 0) return 0.0;
    cv::Mat expected(picture.size(), CV_8UC3, cv::Scalar(0, 0, 0));
    draw_state_text(expected, origin, state);
    const cv::Vec3b color(static_cast<uchar>(state_color(state)[0]),
                          static_cast<uchar>(state_color(state)[1]),
                          static_cast<uchar>(state_color(state)[2]));
    int text_pixels = 0, text_hits = 0, other_pixels = 0, other_hits = 0;
    for (int y = box.y; y < box.br().y; ++y) {
        for (int x = box.x; x < box.br().x; ++x) {
            const bool in_text = expected.at<cv::Vec3b>(y, x) == color;
            const bool has_color = picture.at<cv::Vec3b>(y, x) == color;
            (in_text ? text_pixels : other_pixels) += 1;
            if (has_color) (in_text ? text_hits : other_hits) += 1;
        }
    }
    if (text_pixels == 0) return 0.0;
    return static_cast<double>(text_hits) / text_pixels -
           static_cast<double>(other_hits) / std::max(other_pixels, 1);
}

PreviewSession::PreviewSession(const config::Config& config)
    : config_(config), tracker_(std::make_unique<core::Tracker>(config.core)) {}

PreviewSession::~PreviewSession() = default;

const core::PointerController* PreviewSession::pointer() const noexcept {
    return pointer_ ? &*pointer_ : nullptr;
}

void PreviewSession::set_config(const config::Config& config) {
    config_ = config;
    restart_ = true;
}

void PreviewSession::process(const core::FrameView& frame) {
    if (restart_) {
        tracker_ = std::make_unique<core::Tracker>(config_.core);
        pointer_.reset();
        restart_ = false;
        recovery_from_.reset();
    }
    const auto start = std::chrono::steady_clock::now();
    last_ = tracker_->process(frame);
    const auto spent =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    microseconds_ = average(microseconds_, spent);
    if (previous_ >= 0 && frame.timestamp > previous_) {
        fps_ = average(fps_, 1e6 / static_cast<double>(frame.timestamp - previous_));
    }
    previous_ = frame.timestamp;
    if (!pointer_) {
        pointer_.emplace(config_.core.pointer,
                         static_cast<double>(frame.width) / static_cast<double>(frame.height),
                         config_.core.output);
    }
    if (last_.recovery_from) {
        recovery_from_ = last_.recovery_from;
        recovery_at_ = last_.timestamp;
    }
    const core::PointerCommand command = pointer_->update(last_);
    for (const core::ButtonChange& change : command.button_changes()) {
        if (change.pressed && change.button == core::Button::left) ++presses_;
    }
    ++frames_;
    const cv::Mat pixels(
        frame.height, frame.width, frame.format == core::PixelFormat::bgr ? CV_8UC3 : CV_8UC2,
        const_cast<std::uint8_t*>(frame.data), static_cast<std::size_t>(frame.stride));
    if (frame.format == core::PixelFormat::bgr) {
        pixels.copyTo(bgr_);
    } else {
        cv::cvtColor(pixels, bgr_, cv::COLOR_YUV2BGR_YUYV);
    }
}

cv::Mat PreviewSession::render() const {
    if (bgr_.empty()) return {};
    // A small camera picture (320x240) is shown twice as large, so the status lines fit and the
    // markers stay readable; markers are drawn at the shown size.
    const int scale = bgr_.cols < min_picture_width ? 2 : 1;
    const cv::Size shown(bgr_.cols * scale, bgr_.rows * scale);
    cv::Mat picture(shown.height + status_panel_height, shown.width, CV_8UC3,
                    cv::Scalar(32, 32, 32));
    cv::Mat top = picture(cv::Rect(cv::Point(0, 0), shown));
    cv::resize(bgr_, top, shown, 0, 0, cv::INTER_NEAREST);
    // RECOVERING runs within one frame: its points stay drawn for recovery_hold_us of frame
    // time, long enough to see in a live window.
    core::FrameResult shown_result = last_;
    if (!shown_result.recovery_from && recovery_from_ &&
        last_.timestamp - recovery_at_ <= recovery_hold_us) {
        shown_result.recovery_from = recovery_from_;
    }
    draw_tracker_view(top, *tracker_, shown_result, view_, config_.core.preprocess.edge_threshold);

    const int y0 = shown.height;
    draw_state_text(picture, state_text_origin(y0), last_.state);
    std::string line =
        format_number("%.1f fps", fps_) + format_number("  %.0f us/frame", microseconds_);
    line += last_.area ? format_number("  area %.4f", *last_.area) : std::string("  area -");
    line +=
        last_.has_position ? format_number("  z %+.3f", last_.position.z) : std::string("  z -");
    text(picture, line, {200, y0 + 24}, panel_ink);

    // The click machine: its state, the rise of sqrt(area) over the baseline against press_rise.
    const core::ClickSettings& click = config_.core.pointer.click;
    std::string second = std::string(view_ == BackgroundView::edges ? "edges" : "difference") +
                         (paused_ ? "  PAUSED" : "");
    if (pointer_ && click.mode == core::ClickMode::depth) {
        const core::ClickMachine& machine = pointer_->click_machine();
        second = "click " + std::string(core::to_string(machine.state())) +
                 format_number("  rise %+.3f", machine.rise()) +
                 format_number(" / press %.2f", click.press_rise) + "   " + second;
        // The bar: 0 .. 1.5 x press_rise, ticks at release_rise and press_rise.
        const cv::Rect bar(10, y0 + 50, shown.width - 20, 10);
        const double full = 1.5 * std::max(click.press_rise, 1e-3);
        const auto at = [&](double rise) {
            return bar.x + cvRound(std::clamp(rise / full, 0.0, 1.0) * (bar.width - 1));
        };
        const bool over = machine.rise() >= click.press_rise;
        cv::rectangle(picture, bar, cv::Scalar(80, 80, 80), cv::FILLED);
        cv::rectangle(picture, {bar.x, bar.y}, {at(machine.rise()), bar.br().y - 1},
                      over ? cv::Scalar(0, 140, 255) : cv::Scalar(200, 200, 200), cv::FILLED);
        cv::line(picture, {at(click.press_rise), bar.y - 3}, {at(click.press_rise), bar.br().y + 2},
                 cv::Scalar(0, 0, 255), 2);
        cv::line(picture, {at(click.release_rise), bar.y - 3},
                 {at(click.release_rise), bar.br().y + 2}, cv::Scalar(255, 160, 0), 2);
    }
    text(picture, second, {10, y0 + 44}, panel_ink);
    return picture;
}

}  // namespace raypoint::view
