// SPDX-License-Identifier: MIT
// Transcripts from the tracker's output to the evdev events the virtual device sends: recorded
// core results in (time, state, position, area), the pointer (core) and the event encoder
// (daemon) in between, evdev events out, written as the file sink writes them. Expectations are
// worked out by hand from the settings below, not recorded from a run.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/output/file_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

namespace raypoint::daemon {
namespace {

using core::FrameResult;
using core::TrackerState;

struct Row {
    int ms;
    bool tracking;                    // false: SEARCHING, no target
    double x, y;                      // smoothed position, fractions of the frame
    double size;                      // sqrt(area)
    std::vector<std::string> events;  // "EV_REL REL_X 10", SYN_REPORT lines included
};

core::PointerSettings settings(core::PointerMode mode) {
    core::PointerSettings s;
    s.motion.mode = mode;
    s.motion.mirror = true;
    s.motion.gain = 1000.0;  // device pixels per frame width
    s.motion.dead_zone = 0.0;
    s.motion.acceleration = 0.0;
    s.motion.absolute_max = 1000;
    s.motion.active_left = 0.0;
    s.motion.active_right = 1.0;
    s.motion.active_top = 0.0;
    s.motion.active_bottom = 1.0;
    s.click.mode = core::ClickMode::depth;
    s.click.start_rise = 0.05;
    s.click.press_rise = 0.20;
    s.click.release_rise = 0.10;
    s.click.push_seconds = 0.35;
    s.click.press_hold_seconds = 0.0;  // a press on the first frame at press_rise
    s.click.release_drop = 0.0;
    s.click.refractory_seconds = 0.3;
    s.click.baseline_seconds = 1000.0;  // the baseline stays where tracking started
    s.safety.min_tracking_seconds = 0.2;
    return s;
}

std::string text(const EvdevEvent& e) {
    char buffer[96];
    return std::string(format_event(e, 0, buffer)).substr(2);  // drop the "0 " timestamp
}

void play(core::PointerMode mode, const std::vector<Row>& rows) {
    const core::PointerSettings s = settings(mode);
    core::PointerController pointer(s, 4.0 / 3.0);
    PointerEncoder encoder(device_profile(s.motion));
    for (const Row& row : rows) {
        FrameResult frame;
        frame.timestamp = static_cast<core::Timestamp>(row.ms) * 1000;
        frame.state = row.tracking ? TrackerState::tracking : TrackerState::searching;
        frame.has_target = row.tracking;
        frame.has_position = row.tracking;
        if (row.tracking) {
            frame.centroid = {row.x, row.y};
            frame.area = row.size * row.size;
            frame.position = {row.x, row.y, 0.0};
        }
        std::vector<std::string> got;
        // The batch must outlive the loop: events() is a view into it.
        const EventBatch batch = encoder.encode(pointer.update(frame));
        for (const auto& event : batch.events()) {
            got.push_back(text(event));
        }
        EXPECT_EQ(got, row.events) << "at " << row.ms << " ms";
    }
}

const std::string syn = "EV_SYN SYN_REPORT 0";

TEST(EvdevTranscript, RelativeMotionPushClickAndReleaseOnLoss) {
    play(core::PointerMode::relative,
         {
             {0, false, 0, 0, 0, {}},
             {100, true, 0.50, 0.50, 0.200, {}},  // the first position: nothing to move by
             // The hand moves left in the camera's view: mirrored, the cursor goes right by
             // 0.01 frame widths x 1000.
             {200, true, 0.49, 0.50, 0.200, {"EV_REL REL_X 10", syn}},
             // 0.02 of the height is 0.015 frame widths at 4:3.
             {300, true, 0.49, 0.52, 0.200, {"EV_REL REL_Y 15", syn}},
             {400, true, 0.49, 0.52, 0.200, {}},
             {500, true, 0.49, 0.52, 0.215, {}},                          // +7.5%: a push
             {600, true, 0.49, 0.52, 0.230, {}},                          // +15%
             {700, true, 0.49, 0.52, 0.245, {"EV_KEY BTN_LEFT 1", syn}},  // +22.5%: press
             {800, true, 0.49, 0.52, 0.260, {}},
             {900, false, 0, 0, 0, {"EV_KEY BTN_LEFT 0", syn}},  // lost: released at once
             {1000, false, 0, 0, 0, {}},
         });
}

TEST(EvdevTranscript, MotionDuringAPushIsUndoneByThePress) {
    play(core::PointerMode::relative,
         {
             {0, true, 0.50, 0.50, 0.200, {}},
             {300, true, 0.50, 0.50, 0.200, {}},
             {400, true, 0.50, 0.50, 0.215, {}},  // the push begins
             // Pushing drags the hand 0.005 widths left: the cursor follows, 5 px right...
             {500, true, 0.495, 0.50, 0.230, {"EV_REL REL_X 5", syn}},
             // ...and the press puts it back where the push began, then presses.
             {600, true, 0.495, 0.50, 0.245, {"EV_REL REL_X -5", syn, "EV_KEY BTN_LEFT 1", syn}},
             // Frozen while pressed: motion is not sent.
             {700, true, 0.480, 0.50, 0.245, {}},
             {800, true, 0.480, 0.50, 0.215, {"EV_KEY BTN_LEFT 0", syn}},  // +7.5%: released
         });
}

TEST(EvdevTranscript, AbsoluteModeMapsTheMirroredViewOntoTheScreen) {
    play(core::PointerMode::absolute,
         {
             {0, false, 0, 0, 0, {}},
             // x 0.25 mirrored is 0.75 of the screen: 750 of 0..1000; y 0.5: 500.
             {100, true, 0.25, 0.50, 0.200, {"EV_ABS ABS_X 750", "EV_ABS ABS_Y 500", syn}},
             {200, true, 0.50, 0.50, 0.200, {"EV_ABS ABS_X 500", syn}},  // y unchanged: not sent
             {300, true, 0.50, 0.50, 0.200, {}},
         });
}

}  // namespace
}  // namespace raypoint::daemon
