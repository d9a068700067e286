// SPDX-License-Identifier: MIT
#pragma once
// What the pointer asks the input device to do after one frame: plain data, no device here.

#include <array>
#include <span>
#include <string_view>

namespace raypoint::core {

enum class Button { left, right, middle };

struct ButtonChange {
    Button button = Button::left;
    bool pressed = false;  // true: press, false: release
};

// Emit in this order: the motion (then SYN_REPORT), then each button change in order, each
// followed by SYN_REPORT. Motion goes first because a press may come with the motion that puts
// the cursor back where the push began; a press and its release in the same command (a dwell
// click) need a report between them or the desktop sees nothing.
struct PointerCommand {
    static constexpr int max_changes = 6;  // a release per button plus a click, with room

    int dx = 0;  // relative mode: device pixels, x right
    int dy = 0;  // y down
    bool has_absolute = false;
    int abs_x = 0;  // absolute mode: 0..MotionSettings::absolute_max
    int abs_y = 0;
    std::array<ButtonChange, max_changes> changes{};
    int change_count = 0;
    int wheel = 0;         // REL_WHEEL detents, up positive (a push held moving up or down)
    int wheel_hi_res = 0;  // REL_WHEEL_HI_RES: 120ths of a detent, the same motion finer

    // Returns false (and drops the change) when the command is full.
    bool add(Button button, bool pressed) noexcept;
    std::span<const ButtonChange> button_changes() const noexcept {
        return {changes.data(), static_cast<std::size_t>(change_count)};
    }
    bool empty() const noexcept {
        return dx == 0 && dy == 0 && !has_absolute && change_count == 0 && wheel == 0 &&
               wheel_hi_res == 0;
    }
};

std::string_view to_string(Button button) noexcept;  // "left", "right", "middle"

}  // namespace raypoint::core
