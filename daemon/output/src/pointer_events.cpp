// SPDX-License-Identifier: MIT
#include "raypoint/output/pointer_events.hpp"

#include <linux/input-event-codes.h>

#include <algorithm>

namespace raypoint::daemon {

namespace {

constexpr std::array<core::Button, 3> all_buttons = {core::Button::left, core::Button::right,
                                                     core::Button::middle};

std::size_t index(core::Button button) noexcept {
    return static_cast<std::size_t>(button);
}

}  // namespace

DeviceProfile device_profile(const core::MotionSettings& motion) noexcept {
    return DeviceProfile{motion.mode, motion.absolute_max};
}

void EventBatch::push(std::uint16_t type, std::uint16_t code, std::int32_t value) noexcept {
    // Cannot overflow: capacity covers the largest command (pointer_events.hpp).
    if (size_ < capacity) events_[size_++] = EvdevEvent{type, code, value};
}

std::uint16_t button_code(core::Button button) noexcept {
    switch (button) {
        case core::Button::left:
            return BTN_LEFT;
        case core::Button::right:
            return BTN_RIGHT;
        case core::Button::middle:
            return BTN_MIDDLE;
    }
    return BTN_LEFT;
}

static_assert(key_event_type == EV_KEY);

std::optional<core::Button> button_of_code(std::uint16_t code) noexcept {
    for (core::Button button : all_buttons) {
        if (button_code(button) == code) return button;
    }
    return std::nullopt;
}

PointerEncoder::PointerEncoder(const DeviceProfile& profile) noexcept : profile_(profile) {}

bool PointerEncoder::is_down(core::Button button) const noexcept {
    return down_[index(button)];
}

EventBatch PointerEncoder::encode(const core::PointerCommand& command) noexcept {
    EventBatch batch;
    encode_motion(command, batch);
    for (const core::ButtonChange& change : command.button_changes())
        encode_change(change, batch);
    for (core::Button button : all_buttons) {
        if (!release_pending_[index(button)]) continue;
        release_pending_[index(button)] = false;
        const auto changes = command.button_changes();
        const bool commanded = std::any_of(changes.begin(), changes.end(), [&](const auto& change) {
            return change.button == button;
        });
        if (!commanded) encode_change(core::ButtonChange{button, false}, batch);
    }
    return batch;
}

void PointerEncoder::release_failed(core::Button button) noexcept {
    down_[index(button)] = true;
    release_pending_[index(button)] = true;
}

EventBatch PointerEncoder::release_all() noexcept {
    EventBatch batch;
    for (core::Button button : all_buttons) {
        release_pending_[index(button)] = false;
        encode_change(core::ButtonChange{button, false}, batch);
    }
    return batch;
}

void PointerEncoder::encode_motion(const core::PointerCommand& command,
                                   EventBatch& batch) noexcept {
    const std::size_t before = batch.size();
    switch (profile_.mode) {
        case core::PointerMode::relative:
            if (command.dx != 0) batch.push(EV_REL, REL_X, command.dx);
            if (command.dy != 0) batch.push(EV_REL, REL_Y, command.dy);
            break;
        case core::PointerMode::absolute:
            if (command.has_absolute) {
                const int x = std::clamp(command.abs_x, 0, profile_.absolute_max);
                const int y = std::clamp(command.abs_y, 0, profile_.absolute_max);
                if (x != abs_x_) batch.push(EV_ABS, ABS_X, x);
                if (y != abs_y_) batch.push(EV_ABS, ABS_Y, y);
                abs_x_ = x;
                abs_y_ = y;
            }
            break;
    }
    // libinput reads REL_WHEEL_HI_RES when the device has it and REL_WHEEL otherwise; both go
    // out, in one report, as a high-resolution mouse sends them.
    if (command.wheel != 0) batch.push(EV_REL, REL_WHEEL, command.wheel);
    if (command.wheel_hi_res != 0) batch.push(EV_REL, REL_WHEEL_HI_RES, command.wheel_hi_res);
    if (batch.size() != before) batch.push(EV_SYN, SYN_REPORT, 0);
}

void PointerEncoder::encode_change(core::ButtonChange change, EventBatch& batch) noexcept {
    bool& down = down_[index(change.button)];
    if (down == change.pressed) return;
    down = change.pressed;
    batch.push(EV_KEY, button_code(change.button), change.pressed ? 1 : 0);
    // Its own report: a press and its release in one report would cancel out (a dwell click).
    batch.push(EV_SYN, SYN_REPORT, 0);
}

}  // namespace raypoint::daemon
