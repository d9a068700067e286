// SPDX-License-Identifier: MIT
#pragma once
// The one translation from a PointerCommand to evdev events, shared by the uinput device and the
// file sink so that a recorded stream is exactly what the device would have sent.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
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

// EV_KEY, without <linux/input.h> in every includer.
inline constexpr std::uint16_t key_event_type = 0x01;

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
    // Motion (REL_X, REL_Y or ABS_X, ABS_Y, then REL_WHEEL and REL_WHEEL_HI_RES) and its
    // SYN_REPORT, then a key event
    // and a SYN_REPORT for each of the command's button changes and for each retried release
    // (PointerEncoder::release_failed) of a button the command leaves alone: with its changes all
    // on one button, two retries; with changes on more buttons, fewer.
    static constexpr std::size_t capacity = 5 + 2 * (core::PointerCommand::max_changes + 2);

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

    // The device did not take the release of `button` (EAGAIN: its buffer was full; ENODEV):
    // the button is counted down again and its release goes out with the next batch, unless
    // that batch's command changes the button itself. A lost release must not hold a button.
    void release_failed(core::Button button) noexcept;

    bool is_down(core::Button button) const noexcept;
    const DeviceProfile& profile() const noexcept { return profile_; }

  private:
    void encode_motion(const core::PointerCommand& command, EventBatch& batch) noexcept;
    void encode_change(core::ButtonChange change, EventBatch& batch) noexcept;

    DeviceProfile profile_;
    std::array<bool, 3> down_{};
    std::array<bool, 3> release_pending_{};
    // The device's ABS values start at 0 (uinput_pointer.cpp sets absinfo.value = 0).
    int abs_x_ = 0;
    int abs_y_ = 0;
};

// BTN_LEFT, BTN_RIGHT, BTN_MIDDLE.
std::uint16_t button_code(core::Button button) noexcept;
// The button of BTN_LEFT, BTN_RIGHT or BTN_MIDDLE; none for another code.
std::optional<core::Button> button_of_code(std::uint16_t code) noexcept;

// Writes `batch` event by event with `write` (0 on success or a negative errno, as
// libevdev_uinput_write_event returns) and tells `encoder` of every release that failed. Returns
// the errno of the last failed write, 0 when all succeeded.
template <class Write>
int write_batch(PointerEncoder& encoder, const EventBatch& batch, Write&& write) noexcept {
    int error = 0;
    for (const EvdevEvent& event : batch.events()) {
        const int result = write(event);
        if (result >= 0) continue;
        error = -result;
        if (event.type == key_event_type && event.value == 0) {
            if (const auto button = button_of_code(event.code)) encoder.release_failed(*button);
        }
    }
    return error;
}

}  // namespace raypoint::daemon
