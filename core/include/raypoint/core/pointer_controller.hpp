// SPDX-License-Identifier: MIT
#pragma once
// The whole pointer: tracker results in, device commands out. Joins the motion mapping, the
// click (by depth or dwell) and the safety rules: clicks only after min_tracking_seconds of
// TRACKING, every button released when the target is lost, release_all() for pause and exit.
// Pure: frame time only, no allocation, no exceptions.

#include <array>
#include <optional>

#include "raypoint/core/click_machine.hpp"
#include "raypoint/core/depth_signal.hpp"
#include "raypoint/core/dwell_clicker.hpp"
#include "raypoint/core/pointer_command.hpp"
#include "raypoint/core/pointer_mapper.hpp"
#include "raypoint/core/pointer_settings.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::core {

class PointerController {
  public:
    // frame_aspect: the camera frame's width / height (640x480: 4/3).
    // output: the smoothing the tracker's positions come through (Tracker's OutputSettings),
    // which the click machine's travel follows (region_offset_).
    explicit PointerController(const PointerSettings& settings, double frame_aspect = 4.0 / 3.0,
                               const OutputSettings& output = OutputSettings{}) noexcept;

    // One tracker result, in timestamp order.
    PointerCommand update(const FrameResult& frame) noexcept;

    // Pause, exit, a signal: the releases of every button down, and a fresh start (no motion
    // jump on the next frame, min_tracking_seconds again before a click).
    PointerCommand release_all() noexcept;

    const ClickMachine& click_machine() const noexcept { return clicker_; }
    const DepthSignal& depth_signal() const noexcept { return depth_; }
    DwellState dwell_state() const noexcept { return dweller_.state(); }
    bool is_down(Button button) const noexcept { return down_[index(button)]; }

  private:
    static std::size_t index(Button button) noexcept { return static_cast<std::size_t>(button); }
    void change(PointerCommand& command, Button button, bool pressed) noexcept;
    void release_down(PointerCommand& command) noexcept;
    void depth_click(const ClickStep& step, const Motion& motion, PointerCommand& command) noexcept;
    void scroll(double up, PointerCommand& command) noexcept;  // up: frame widths
    // `chained`: the reported centroid less the region's on a frame the movement's chain led
    // (FrameResult::followed), frame widths.
    void follow_region(bool has_target, cv::Point2d centroid, cv::Point2d chained,
                       Timestamp now) noexcept;

    PointerSettings settings_;
    double frame_aspect_;
    PointerMapper mapper_;
    DepthSignal depth_;
    ClickMachine clicker_;
    DwellClicker dweller_;
    std::optional<Timestamp> tracking_since_;
    // ClickSettings::push_region_jump: the centroid's jumps on frames whose size step the depth
    // signal took out (the region's, not the target's), summed since the target was picked, and
    // that sum as the position's smoothing has passed it on so far (the EMA's weight for the
    // frame's interval; One Euro's is taken as 0, passed on at once).
    cv::Point2d region_jumps_;
    cv::Point2d region_offset_;
    // The same for the steps DepthSignal::stepped() saw and absorbed() left in (at 10 fps, as
    // a push's possible growth): HOLDING's position leaves them out.
    cv::Point2d step_jumps_;
    cv::Point2d step_offset_;
    // The chain's point less the region's centroid, smoothed alike: the position less it is
    // the region's, which the click machine judges a push by.
    cv::Point2d chain_offset_;
    cv::Point2d last_centroid_;
    cv::Point2d last_jump_;
    Timestamp last_centroid_at_ = 0;
    bool has_last_centroid_ = false;
    OutputSettings output_;
    std::array<bool, 3> down_{};
    // Relative: device pixels emitted since the push began, undone by the press.
    cv::Point undo_;
    // Absolute: where the cursor was before the push began, restored by the press.
    std::optional<cv::Point> before_push_;
    // The wheel: hi-res units (1/120 detent) not yet sent, and all sent, whose whole detents
    // REL_WHEEL reports.
    double wheel_remainder_ = 0.0;
    long long wheel_hi_res_ = 0;
};

}  // namespace raypoint::core
