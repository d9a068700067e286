// SPDX-License-Identifier: MIT
#pragma once
// The virtual pointer the desktop sees: a uinput device made with libevdev, relative (a mouse) or
// absolute (a tablet like QEMU's) as the pointer mode says.

#include <memory>
#include <string>
#include <string_view>

#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

struct libevdev_uinput;

namespace raypoint::daemon {

// Creating the device failed: names the call, /dev/uinput, strerror and the fix.
class UinputError : public OutputError {
  public:
    UinputError(std::string_view call, int error);
    int error() const noexcept { return error_; }  // the errno

  private:
    int error_;
};

// The message of UinputError, e.g. "libevdev_uinput_create_from_device on /dev/uinput:
// Permission denied; add the udev rule ...". `error` is a positive errno.
std::string uinput_error_message(std::string_view call, int error);

class UinputPointer final : public EventSink {
  public:
    static constexpr std::string_view device_name = "raypoint virtual pointer";
    static constexpr std::string_view uinput_path = "/dev/uinput";

    // Creates the device (LIBEVDEV_UINPUT_OPEN_MANAGED); throws UinputError.
    explicit UinputPointer(const DeviceProfile& profile);
    // Releases every button down, then destroys the device.
    ~UinputPointer() override;

    void emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept override;
    void release_all(core::Timestamp timestamp) noexcept override;
    std::string_view name() const override { return "uinput"; }
    int last_error() const noexcept override { return last_error_; }
    long long failed_writes() const noexcept override { return failed_writes_; }

    // /dev/input/eventN of the device; empty when libevdev cannot tell (no sysfs).
    std::string_view devnode() const noexcept { return devnode_; }
    const DeviceProfile& profile() const noexcept { return encoder_.profile(); }

  private:
    struct Destroy {
        void operator()(libevdev_uinput* device) const noexcept;
    };

    void write(const EventBatch& batch) noexcept;

    std::unique_ptr<libevdev_uinput, Destroy> device_;
    std::string devnode_;
    PointerEncoder encoder_;
    int last_error_ = 0;
    long long failed_writes_ = 0;
};

}  // namespace raypoint::daemon
