// SPDX-License-Identifier: MIT
#pragma once
// The one translation from a PointerCommand to evdev events, shared by the uinput device and the
// file sink so that a recorded stream is exactly what the device would have sent.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "raypoint/core/pointer_command.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::daemon {

// What the virtual device is, fixed when it is created: the pointer mode picks the profile.
struct DeviceProfile {
    core::PointerMode mode = core::PointerMode::relative;
    int absolute_max = 65535;  // absolute: ABS_X and ABS_Y run 0..absolute_max
};

DeviceProfile device_profile(const core::MotionSettings& motion) noexcept;

// struct input_event without the time: the kernel stamps what uinput writes.
struct EvdevEvent {
    std::uint16_t type = 0;
    std::uint16_t code = 0;
    std::int32_t value = 0;

    friend bool operator==(const EvdevEvent&, const EvdevEvent&) = default;
};

// The events of one command, in a fixed array so the per-frame path never allocates.
class EventBatch {
  public:
    // Motion (REL_X, REL_Y or ABS_X, ABS_Y, then REL_WHEEL) and its SYN_REPORT, then a key event
    // and a SYN_REPORT for each of the command's button changes.
    static constexpr std::size_t capacity = 4 + 2 * core::PointerCommand::max_changes;

    void push(std::uint16_t type, std::uint16_t code, std::int32_t value) noexcept;
    std::span<const EvdevEvent> events() const noexcept { return {events_.data(), size_}; }
    std::size_t size() const noexcept { return size_; }
    bool empty() const noexcept { return size_ == 0; }

  private:
    std::array<EvdevEvent, capacity> events_{};
    std::size_t size_ = 0;
};

// Stateful because the kernel's input core drops what does not change the device's state: a zero
// REL value, an ABS value equal to the current one, a press of a pressed key or a release of a
// released one, and a SYN_REPORT with nothing before it. The encoder drops the same, so its
// output is what a reader of /dev/input/eventN receives, and it knows which buttons are down.
class PointerEncoder {
  public:
    explicit PointerEncoder(const DeviceProfile& profile) noexcept;

    // Relative profile: dx, dy; absolute profile: abs_x, abs_y (clamped to 0..absolute_max)
    // when has_absolute. The other profile's motion is ignored: the device has no such axes.
    EventBatch encode(const core::PointerCommand& command) noexcept;
    // A release and a SYN_REPORT for each button down, in the order left, right, middle.
    EventBatch release_all() noexcept;

    bool is_down(core::Button button) const noexcept;
    const DeviceProfile& profile() const noexcept { return profile_; }

  private:
    void encode_motion(const core::PointerCommand& command, EventBatch& batch) noexcept;
    void encode_change(core::ButtonChange change, EventBatch& batch) noexcept;

    DeviceProfile profile_;
    std::array<bool, 3> down_{};
    // The device's ABS values start at 0 (uinput_pointer.cpp sets absinfo.value = 0).
    int abs_x_ = 0;
    int abs_y_ = 0;
};

// BTN_LEFT, BTN_RIGHT, BTN_MIDDLE.
std::uint16_t button_code(core::Button button) noexcept;

}  // namespace raypoint::daemon
