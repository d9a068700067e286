// SPDX-License-Identifier: MIT
#pragma once
// The preview's frame-by-frame work, without a window: each frame is tracked, timed and fed to
// the pointer (whose commands go nowhere: the click machine is what the preview shows), and
// render() gives the picture a window shows or a screenshot saves: the frame with the tracker's
// view drawn on it, and a status panel under it.

#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "raypoint/config/config.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/view/overlay.hpp"

namespace raypoint::view {

// The status panel under the frame: two lines of text, then a bar of the click rise.
constexpr int status_panel_height = 70;

// The state's name in capitals, in state_color(state) without anti-aliasing, at the panel's
// first line. A test compares a screenshot's pixels with this drawing.
cv::Point state_text_origin(int frame_rows) noexcept;
void draw_state_text(cv::Mat& image, cv::Point origin, core::TrackerState state);
// The share of the pixels draw_state_text() would colour for `state` that have its colour in
// `picture` (a render() output whose frame is `frame_rows` high), minus the share of the text
// box's other pixels in that colour: near 1 when the text is there, low otherwise.
double state_text_match(const cv::Mat& picture, int frame_rows, core::TrackerState state);

class PreviewSession {
  public:
    explicit PreviewSession(const config::Config& config);
    ~PreviewSession();

    // One frame, BGR or YUYV: tracked (timed on the steady clock), then stepped through the
    // pointer. The frame is kept (as BGR) for render().
    void process(const core::FrameView& frame);
    // The last frame with the overlay and the status panel; empty before the first frame.
    cv::Mat render() const;

    const config::Config& config() const noexcept { return config_; }
    // New settings: the tracker and the pointer start again from the next frame (a tracker's
    // settings are fixed at construction). Until then render() already draws the edges at the
    // new edge_threshold, so a paused frame shows what a threshold would do.
    void set_config(const config::Config& config);

    BackgroundView view() const noexcept { return view_; }
    void set_view(BackgroundView view) noexcept { view_ = view; }
    bool paused() const noexcept { return paused_; }
    void set_paused(bool paused) noexcept { paused_ = paused; }

    const core::FrameResult& last_result() const noexcept { return last_; }
    const core::PointerController* pointer() const noexcept;
    int presses() const noexcept { return presses_; }
    int frames() const noexcept { return frames_; }

  private:
    config::Config config_;
    std::unique_ptr<core::Tracker> tracker_;
    std::optional<core::PointerController> pointer_;
    bool restart_ = false;
    cv::Mat bgr_;
    core::FrameResult last_;
    BackgroundView view_ = BackgroundView::edges;
    bool paused_ = false;
    double fps_ = 0.0;           // from the frames' timestamps, averaged
    double microseconds_ = 0.0;  // the core's time a frame, averaged
    core::Timestamp previous_ = -1;
    std::optional<cv::Point2d> recovery_from_;  // the last frame that ran RECOVERING
    core::Timestamp recovery_at_ = 0;
    int presses_ = 0;
    int frames_ = 0;
};

}  // namespace raypoint::view
