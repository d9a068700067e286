// SPDX-License-Identifier: MIT
#pragma once
// Transcript tests for the pointer: one table row a frame, the tracker's result in (time, state,
// smoothed x and y, sqrt(area)) and the device command out, written as text:
//   "rel 10 -3"        relative motion (dx, dy), when not zero
//   "abs 500 250"      absolute position, when there is one
//   "+left" / "-left"  a button press / release, in order
//   "wheel 1"          wheel detents, when not zero
//   "hires 120"        REL_WHEEL_HI_RES (120ths of a detent), when not zero
// joined by single spaces in that order; "" is no command at all. A row may also name the click
// state after the frame ("idle", "pressed", ...; nullptr: not checked).

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/core/pointer_controller.hpp"

namespace raypoint::test {

using core::TrackerState;

// Shorthands for the tables' state column, one letter wide so that the columns stay aligned;
// the naming rule's lower case would shadow the tests' own `s` and `t`.
constexpr TrackerState T = TrackerState::tracking;   // NOLINT(readability-identifier-naming)
constexpr TrackerState S = TrackerState::searching;  // NOLINT(readability-identifier-naming)

// sqrt(area) of the frame that picks a target: TRACKING, but no area and no position yet.
constexpr double picked = -1.0;

// The transcripts' camera frame: 4:3, as 160x120.
constexpr double aspect = 4.0 / 3.0;

// The transcripts' pointer before each file's own settings: relative, mirrored, 1000 device
// pixels a frame width, no dead zone and no acceleration, so the out column is hand motion
// times 1000.
inline core::PointerSettings linear_pointer() {
    core::PointerSettings s;
    s.motion.mode = core::PointerMode::relative;
    s.motion.mirror = true;
    s.motion.gain = 1000.0;
    s.motion.dead_zone = 0.0;
    s.motion.acceleration = 0.0;
    return s;
}

// The click transcripts' settings: click by depth, start 5%, press 20%, release 10%, push
// 0.35 s, refractory 0.3 s, drag 0.8 s, no hold, no release_drop, a baseline held constant
// (time constant 1000 s), clicks allowed after 0.2 s of tracking; the depth signal and the
// push model off (test_click_signal.cpp turns them on).
inline core::PointerSettings depth_pointer() {
    core::PointerSettings s = linear_pointer();
    s.click.mode = core::ClickMode::depth;
    s.click.start_rise = 0.05;
    s.click.press_rise = 0.20;
    s.click.release_rise = 0.10;
    s.click.push_seconds = 0.35;
    s.click.refractory_seconds = 0.3;
    s.click.drag_seconds = 0.8;
    s.click.baseline_seconds = 1000.0;
    s.click.press_hold_seconds = 0.0;
    s.click.jump_hold_seconds = 0.0;
    s.click.release_drop = 0.0;
    s.click.release_share = 0.0;
    s.click.glitch_jump = 0.0;
    s.click.glitch_leap = 0.0;
    s.click.glitch_light = 0.0;
    s.click.push_travel = 0.0;
    s.click.travel_hold_seconds = 0.0;
    s.click.push_dip = 0.0;
    s.click.settle_seconds = 0.0;
    s.safety.min_tracking_seconds = 0.2;
    return s;
}

// depth_pointer() with the gestures of click_machine.hpp on: right click after 0.5 s still, 100
// wheel detents a frame width, double click within 0.6 s, a hold radius of 0.02 frame widths.
inline core::PointerSettings gesture_pointer() {
    core::PointerSettings s = depth_pointer();
    s.click.right_seconds = 0.5;
    s.click.scroll_gain = 100.0;
    s.click.double_seconds = 0.6;
    s.click.hold_radius = 0.02;
    return s;
}

struct PointerRow {
    double ms;           // frame time, milliseconds
    TrackerState state;  // the tracker's state after the frame
    double x = 0.0;      // smoothed position, fractions of the frame
    double y = 0.0;
    double size = 0.0;            // sqrt(area), fraction of the frame; `picked`: unknown
    const char* click = nullptr;  // expected ClickState (or DwellState) name, or not checked
    std::string out;              // expected command
};

inline std::string format(const core::PointerCommand& command) {
    std::string text;
    const auto put = [&text](const std::string& part) {
        if (!text.empty()) text += ' ';
        text += part;
    };
    if (command.dx != 0 || command.dy != 0) {
        put("rel " + std::to_string(command.dx) + " " + std::to_string(command.dy));
    }
    if (command.has_absolute) {
        put("abs " + std::to_string(command.abs_x) + " " + std::to_string(command.abs_y));
    }
    for (const auto& change : command.button_changes()) {
        put(std::string(change.pressed ? "+" : "-").append(core::to_string(change.button)));
    }
    if (command.wheel != 0) put("wheel " + std::to_string(command.wheel));
    if (command.wheel_hi_res != 0) put("hires " + std::to_string(command.wheel_hi_res));
    return text;
}

inline core::FrameResult frame_of(const PointerRow& row, std::int64_t index) {
    core::FrameResult frame;
    frame.frame = index;
    frame.timestamp = static_cast<core::Timestamp>(std::llround(row.ms * 1000.0));
    frame.state = row.state;
    const bool tracking = row.state == TrackerState::tracking;
    frame.has_target = tracking;
    if (tracking && row.size > 0.0) {
        frame.centroid = {row.x, row.y};
        frame.inner = frame.centroid;
        frame.area = row.size * row.size;
        frame.has_position = true;
        // z is the tracker's smoothed sqrt(area) change; the pointer reads the raw area.
        frame.position = {row.x, row.y, 0.0};
    }
    return frame;
}

// Which state name a row's `click` column is checked against.
enum class Watch { click, dwell };

// Feeds `rows` to `pointer`, checking each command (and state, where the row names one).
inline std::vector<core::PointerCommand> play(core::PointerController& pointer,
                                              const std::vector<PointerRow>& rows,
                                              Watch watch = Watch::click) {
    std::vector<core::PointerCommand> commands;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const PointerRow& row = rows[i];
        SCOPED_TRACE(::testing::Message() << "row " << i << " at " << row.ms << " ms");
        const core::PointerCommand command =
            pointer.update(frame_of(row, static_cast<std::int64_t>(i)));
        EXPECT_EQ(format(command), row.out);
        if (row.click != nullptr) {
            const std::string_view state = watch == Watch::click
                                               ? to_string(pointer.click_machine().state())
                                               : to_string(pointer.dwell_state());
            EXPECT_EQ(state, std::string_view(row.click));
        }
        commands.push_back(command);
    }
    return commands;
}

}  // namespace raypoint::test
