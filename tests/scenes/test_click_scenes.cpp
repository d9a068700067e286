// SPDX-License-Identifier: MIT
// Click by depth end to end: rendered clips through the real tracker and the pointer with its
// default settings. The push scene's paper hand comes to rest at 4.5 s and pushes toward the
// camera at 5.0 s and 6.6 s (0.3 s in, 0.1 s held, 0.3 s out, 25% closer): exactly two clicks,
// each within 0.5 s of its push, and the cursor still while the button is down. Scenes with no
// push must not click at all.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/scene/renderer.hpp"

namespace {

using raypoint::core::Button;
using raypoint::core::ClickState;

struct Click {
    double pressed = 0.0;            // s
    double released = 0.0;           // s; 0 while still down
    int moved_while_down = 0;        // |dx| + |dy| emitted between press and release
    double peak_rise = 0.0;          // sqrt(area) over the baseline, largest while down
    cv::Point undone;                // the press's motion: the push's own motion taken back
    bool lands_where_aimed = false;  // the cursor at the press is where the push began
};

struct Played {
    std::vector<Click> clicks;
    int presses = 0;
    int releases = 0;
};

Played play(const std::string& name) {
    const raypoint::scene::SceneSpec spec = raypoint::scene::preset(name);
    const raypoint::scene::Renderer renderer(spec);
    const raypoint::core::Settings settings;
    raypoint::core::Tracker tracker(settings);
    raypoint::core::PointerController pointer(settings.pointer,
                                              static_cast<double>(spec.width) / spec.height);
    Played played;
    cv::Point cursor;  // sum of the relative motion so far
    cv::Point aimed;   // the cursor on the last frame before the push began
    for (int index = 0; index < renderer.frame_count(); ++index) {
        const auto frame = renderer.render(index);
        const double seconds = renderer.frame_time(index);
        const raypoint::core::FrameView view{frame.bgr.data,
                                             frame.bgr.cols,
                                             frame.bgr.rows,
                                             static_cast<int>(frame.bgr.step),
                                             raypoint::core::PixelFormat::bgr,
                                             raypoint::core::seconds_to_us(seconds)};
        const raypoint::core::FrameResult result = tracker.process(view);
        const raypoint::core::PointerCommand command = pointer.update(result);
        const auto& machine = pointer.click_machine();
        cursor += cv::Point(command.dx, command.dy);
        const bool down_before = !played.clicks.empty() && played.clicks.back().released == 0.0;
        if (down_before) {
            played.clicks.back().moved_while_down += std::abs(command.dx) + std::abs(command.dy);
        }
        for (const auto& change : command.button_changes()) {
            EXPECT_EQ(change.button, Button::left);
            if (change.pressed) {
                ++played.presses;
                played.clicks.push_back(Click{seconds, 0.0, 0, machine.rise(),
                                              cv::Point(command.dx, command.dy), cursor == aimed});
            } else {
                ++played.releases;
                if (!played.clicks.empty()) played.clicks.back().released = seconds;
            }
        }
        if (machine.state() == ClickState::idle) aimed = cursor;
        if (machine.state() == ClickState::pressed || machine.state() == ClickState::dragging) {
            Click& click = played.clicks.back();
            click.peak_rise = std::max(click.peak_rise, machine.rise());
        }
        if (result.area && index % 3 == 0 && name == "push" && seconds >= 4.9 && seconds <= 7.4) {
            std::printf("%s %.3f s  sqrt(area) %.4f  baseline %.4f  rise %+.3f  z %+.4f  %s\n",
                        name.c_str(), seconds, std::sqrt(*result.area), machine.baseline(),
                        machine.rise(), result.position.z,
                        std::string(to_string(machine.state())).c_str());
        }
    }
    for (const Click& click : played.clicks) {
        std::printf(
            "%s click: pressed %.3f s, released %.3f s, peak rise %.3f, undone (%d, %d) px, "
            "moved %d px while down\n",
            name.c_str(), click.pressed, click.released, click.peak_rise, click.undone.x,
            click.undone.y, click.moved_while_down);
    }
    return played;
}

TEST(ClickScenes, PushClicksTwiceWhereItAimed) {
    const Played played = play("push");
    ASSERT_EQ(played.presses, 2);
    ASSERT_EQ(played.releases, 2);
    ASSERT_EQ(played.clicks.size(), 2U);
    const double pushes[] = {5.0, 6.6};
    for (std::size_t i = 0; i < 2; ++i) {
        const Click& click = played.clicks[i];
        SCOPED_TRACE(::testing::Message() << "push at " << pushes[i] << " s");
        EXPECT_GT(click.pressed, pushes[i]);
        EXPECT_LT(click.pressed, pushes[i] + 0.5);
        EXPECT_GT(click.released, click.pressed);
        // A click, not a drag: up again before drag_seconds (0.8 s).
        EXPECT_LT(click.released - click.pressed, 0.8);
        EXPECT_EQ(click.moved_while_down, 0);
        EXPECT_TRUE(click.lands_where_aimed);
    }
}

TEST(ClickScenes, NoPushNoClick) {
    for (const char* name : {"nonconvex", "pause"}) {
        SCOPED_TRACE(name);
        const Played played = play(name);
        EXPECT_EQ(played.presses, 0);
        EXPECT_EQ(played.releases, 0);
    }
}

}  // namespace
