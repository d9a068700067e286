// SPDX-License-Identifier: MIT
#include "raypoint/output/uinput_pointer.hpp"

#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>
#include <linux/input.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <string>

namespace raypoint::daemon {

namespace {

struct FreeEvdev {
    void operator()(libevdev* device) const noexcept { libevdev_free(device); }
};
using EvdevPtr = std::unique_ptr<libevdev, FreeEvdev>;

constexpr std::array<unsigned int, 3> button_codes = {BTN_LEFT, BTN_RIGHT, BTN_MIDDLE};

// ABS resolution is units per mm. The device has no physical size, but a resolution of 0 makes
// libinput substitute 1 unit/mm, which would describe a 65 m wide tablet to anything that reasons
// in millimetres; the range spread over a nominal 500 mm (a 23" screen's width) is plausible.
constexpr int nominal_width_mm = 500;

void enable(libevdev* device, unsigned int type, unsigned int code, const void* data = nullptr) {
    // libevdev_enable_event_code returns -1 without setting errno: only a bad type or code fails.
    if (libevdev_enable_event_code(device, type, code, data) != 0) {
        throw UinputError("libevdev_enable_event_code", EINVAL);
    }
}

void enable_property(libevdev* device, unsigned int property) {
    if (libevdev_enable_property(device, property) != 0) {
        throw UinputError("libevdev_enable_property", EINVAL);
    }
}

// The template uinput copies. Both profiles have the three buttons and the wheel, in detents
// and in 120ths (QEMU's tablet
// has them too), so a click or scroll means the same in either mode.
EvdevPtr make_template(const DeviceProfile& profile) {
    EvdevPtr device(libevdev_new());
    if (!device) throw UinputError("libevdev_new", ENOMEM);
    libevdev_set_name(device.get(), std::string(UinputPointer::device_name).c_str());
    libevdev_set_id_bustype(device.get(), BUS_VIRTUAL);
    for (unsigned int code : button_codes)
        enable(device.get(), EV_KEY, code);
    enable(device.get(), EV_REL, REL_WHEEL);
    enable(device.get(), EV_REL, REL_WHEEL_HI_RES);
    switch (profile.mode) {
        case core::PointerMode::relative:
            enable(device.get(), EV_REL, REL_X);
            enable(device.get(), EV_REL, REL_Y);
            enable_property(device.get(), INPUT_PROP_POINTER);
            break;
        case core::PointerMode::absolute: {
            // ABS_X/ABS_Y with BTN_LEFT and no BTN_TOUCH or pen tool: udev tags it
            // ID_INPUT_MOUSE (its path for VMware's and QEMU's absolute mice) and libinput's
            // fallback dispatch sends LIBINPUT_EVENT_POINTER_MOTION_ABSOLUTE, without
            // acceleration. INPUT_PROP_DIRECT says what is true: a position is a screen position.
            input_absinfo axis{};
            axis.value = 0;  // PointerEncoder starts from 0 too, to drop the same repeats
            axis.minimum = 0;
            axis.maximum = profile.absolute_max;
            axis.resolution = std::max(1, (profile.absolute_max + 1) / nominal_width_mm);
            enable(device.get(), EV_ABS, ABS_X, &axis);
            enable(device.get(), EV_ABS, ABS_Y, &axis);
            enable_property(device.get(), INPUT_PROP_DIRECT);
            break;
        }
    }
    return device;
}

std::string_view advice(int error) noexcept {
    switch (error) {
        case EACCES:
            return "add the udev rule packaging/70-raypoint-uinput.rules (TAG+=\"uaccess\") or "
                   "join the group that owns /dev/uinput";
        case ENOENT:
        case ENODEV:  // the node exists (static_node) but no driver behind it yet
            return "load the module: sudo modprobe uinput (packaging installs "
                   "modules-load.d/raypoint.conf)";
        case EPERM:
            return "a sandbox or container denies the device; run raypoint outside it or allow "
                   "/dev/uinput in it";
        default:
            return "";
    }
}

}  // namespace

std::string uinput_error_message(std::string_view call, int error) {
    std::string message(call);
    message += " on ";
    message += UinputPointer::uinput_path;
    message += ": ";
    message += std::strerror(error);
    const std::string_view fix = advice(error);
    if (!fix.empty()) {
        message += "; ";
        message += fix;
    }
    return message;
}

UinputError::UinputError(std::string_view call, int error)
    : OutputError(uinput_error_message(call, error)), error_(error) {}

void UinputPointer::Destroy::operator()(libevdev_uinput* device) const noexcept {
    libevdev_uinput_destroy(device);
}

UinputPointer::UinputPointer(const DeviceProfile& profile) : encoder_(profile) {
    const EvdevPtr device = make_template(profile);
    libevdev_uinput* created = nullptr;
    const int result =
        libevdev_uinput_create_from_device(device.get(), LIBEVDEV_UINPUT_OPEN_MANAGED, &created);
    if (result < 0) throw UinputError("libevdev_uinput_create_from_device", -result);
    device_.reset(created);
    if (const char* node = libevdev_uinput_get_devnode(created)) devnode_ = node;
}

UinputPointer::~UinputPointer() {
    release_all(0);
}

void UinputPointer::emit(const core::PointerCommand& command,
                         core::Timestamp /*timestamp*/) noexcept {
    write(encoder_.encode(command));
}

void UinputPointer::release_all(core::Timestamp /*timestamp*/) noexcept {
    write(encoder_.release_all());
}

void UinputPointer::write(const EventBatch& batch) noexcept {
    // The kernel stamps each event itself; the frame's timestamp is for the file sink only.
    const int error = write_batch(encoder_, batch, [&](const EvdevEvent& event) {
        return libevdev_uinput_write_event(device_.get(), event.type, event.code, event.value);
    });
    if (error != 0) {
        last_error_ = error;
        ++failed_writes_;
    }
}

}  // namespace raypoint::daemon
