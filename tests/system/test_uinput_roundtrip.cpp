// SPDX-License-Identifier: MIT
// The uinput device on a real kernel, as libevdev's own test_uinput_events does: create the
// device, open its /dev/input/eventN with libevdev, emit motion and clicks through UinputPointer,
// read the events back and compare them with the shared encoder's (what --sink file writes).
// Exits 77 (CTest: skipped) with the reason when there is no usable /dev/uinput or no devnode,
// as in containers; 1 on a mismatch.

#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "raypoint/output/pointer_events.hpp"
#include "raypoint/output/uinput_pointer.hpp"

namespace {

using raypoint::core::Button;
using raypoint::core::PointerCommand;
using raypoint::core::PointerMode;
using namespace raypoint::daemon;

constexpr int skip = 77;

struct Skip {
    std::string reason;
};

struct Failure {
    std::string reason;
};

struct FreeEvdev {
    void operator()(libevdev* device) const noexcept { libevdev_free(device); }
};

// An fd and the libevdev reading it; closes the fd when done.
struct Reader {
    int fd = -1;
    std::unique_ptr<libevdev, FreeEvdev> device;

    Reader() = default;
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;
    ~Reader() {
        device.reset();
        if (fd >= 0) close(fd);
    }
};

// udev may still be creating the node or applying its permissions: retry for a while.
void open_devnode(const UinputPointer& pointer, Reader& reader) {
    const std::string node(pointer.devnode());
    if (node.empty())
        throw Skip{"libevdev_uinput_get_devnode found no /dev/input/eventN (no sysfs?)"};
    int error = 0;
    for (int attempt = 0; attempt < 40; ++attempt) {
        reader.fd = open(node.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (reader.fd >= 0) break;
        error = errno;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (reader.fd < 0) {
        // The device works, but this user may not read its node: only root and the input group
        // can (the uaccess rule covers /dev/uinput, not the event nodes).
        throw Skip{"cannot open " + node + " to read the events back: " + std::strerror(error) +
                   (error == EACCES ? " (run as root or in the input group)" : "")};
    }
    libevdev* device = nullptr;
    const int result = libevdev_new_from_fd(reader.fd, &device);
    if (result < 0) throw Failure{"libevdev_new_from_fd " + node + ": " + std::strerror(-result)};
    reader.device.reset(device);
}

void check_device(libevdev* device, const DeviceProfile& profile) {
    if (libevdev_get_name(device) != UinputPointer::device_name) {
        throw Failure{std::string("device name is ") + libevdev_get_name(device)};
    }
    if (libevdev_get_id_bustype(device) != BUS_VIRTUAL) throw Failure{"bus is not BUS_VIRTUAL"};
    for (unsigned int code : {BTN_LEFT, BTN_RIGHT, BTN_MIDDLE}) {
        if (!libevdev_has_event_code(device, EV_KEY, code)) throw Failure{"a button is missing"};
    }
    if (!libevdev_has_event_code(device, EV_REL, REL_WHEEL)) throw Failure{"REL_WHEEL is missing"};
    if (!libevdev_has_event_code(device, EV_REL, REL_WHEEL_HI_RES)) {
        throw Failure{"REL_WHEEL_HI_RES is missing"};
    }
    switch (profile.mode) {
        case PointerMode::relative:
            if (!libevdev_has_event_code(device, EV_REL, REL_X) ||
                !libevdev_has_event_code(device, EV_REL, REL_Y) ||
                libevdev_has_event_type(device, EV_ABS) ||
                !libevdev_has_property(device, INPUT_PROP_POINTER)) {
                throw Failure{"relative profile: wrong axes or properties"};
            }
            break;
        case PointerMode::absolute:
            if (libevdev_has_event_code(device, EV_REL, REL_X) ||
                libevdev_get_abs_maximum(device, ABS_X) != profile.absolute_max ||
                libevdev_get_abs_maximum(device, ABS_Y) != profile.absolute_max ||
                libevdev_get_abs_minimum(device, ABS_X) != 0 ||
                libevdev_get_abs_resolution(device, ABS_X) <= 0 ||
                !libevdev_has_property(device, INPUT_PROP_DIRECT)) {
                throw Failure{"absolute profile: wrong axes, range or properties"};
            }
            break;
    }
}

// Reads until `count` events arrived or two seconds passed.
std::vector<EvdevEvent> read_events(Reader& reader, std::size_t count) {
    std::vector<EvdevEvent> events;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (events.size() < count && std::chrono::steady_clock::now() < deadline) {
        input_event event{};
        const int result =
            libevdev_next_event(reader.device.get(), LIBEVDEV_READ_FLAG_NORMAL, &event);
        if (result == LIBEVDEV_READ_STATUS_SUCCESS) {
            events.push_back(EvdevEvent{event.type, event.code, event.value});
        } else if (result == -EAGAIN) {
            pollfd wait{reader.fd, POLLIN, 0};
            poll(&wait, 1, 100);
        } else if (result == LIBEVDEV_READ_STATUS_SYNC) {
            throw Failure{"the kernel dropped events (SYN_DROPPED)"};
        } else {
            throw Failure{std::string("libevdev_next_event: ") + std::strerror(-result)};
        }
    }
    return events;
}

std::string describe(const std::vector<EvdevEvent>& events) {
    std::string text;
    for (const EvdevEvent& event : events) {
        text += "  ";
        text += libevdev_event_type_get_name(event.type);
        text += " ";
        text += libevdev_event_code_get_name(event.type, event.code);
        text.append(" ").append(std::to_string(event.value)).append("\n");
    }
    return text;
}

std::vector<PointerCommand> commands(PointerMode mode) {
    PointerCommand first;  // motion, then a press
    if (mode == PointerMode::relative) {
        first.dx = 7;
        first.dy = -3;
    } else {
        first.has_absolute = true;
        first.abs_x = 1200;
        first.abs_y = 34000;
    }
    first.add(Button::left, true);
    PointerCommand second;  // release, and a dwell-like click of the right button
    second.add(Button::left, false);
    second.add(Button::right, true);
    second.add(Button::right, false);
    PointerCommand third;  // a wheel detent and a middle press left down for release_all
    third.wheel = -1;
    third.wheel_hi_res = -120;
    third.add(Button::middle, true);
    return {first, second, third};
}

void round_trip(const DeviceProfile& profile, const char* label) {
    std::unique_ptr<UinputPointer> pointer;
    try {
        pointer = std::make_unique<UinputPointer>(profile);
    } catch (const UinputError& error) {
        // Only "cannot open /dev/uinput" skips; any other refusal is a bug in the profile.
        const int code = error.error();
        if (code == EACCES || code == EPERM || code == ENOENT || code == ENODEV) {
            throw Skip{error.what()};
        }
        throw Failure{error.what()};
    }
    Reader reader;
    open_devnode(*pointer, reader);
    check_device(reader.device.get(), profile);

    PointerEncoder expected_encoder(profile);
    std::vector<EvdevEvent> expected;
    raypoint::core::Timestamp t = 0;
    for (const PointerCommand& command : commands(profile.mode)) {
        const EventBatch batch = expected_encoder.encode(command);
        expected.insert(expected.end(), batch.events().begin(), batch.events().end());
        pointer->emit(command, t += 33333);
    }
    const EventBatch releases = expected_encoder.release_all();
    expected.insert(expected.end(), releases.events().begin(), releases.events().end());
    pointer->release_all(t);
    if (pointer->last_error() != 0) {
        throw Failure{std::string("a write failed: ") + std::strerror(pointer->last_error())};
    }

    const std::vector<EvdevEvent> got = read_events(reader, expected.size());
    if (got != expected) {
        throw Failure{std::string(label) + ": events differ\nexpected:\n" + describe(expected) +
                      "read back:\n" + describe(got)};
    }
    std::cout << label << ": " << got.size() << " events read back from " << pointer->devnode()
              << " as written\n";
}

}  // namespace

int main() {
    // No check for /dev/uinput up front: UinputPointer's own error (with its advice) is the reason.
    try {
        round_trip(DeviceProfile{PointerMode::relative, 65535}, "relative");
        round_trip(DeviceProfile{PointerMode::absolute, 65535}, "absolute");
    } catch (const Skip& reason) {
        std::cout << "skipped: " << reason.reason << "\n";
        return skip;
    } catch (const Failure& failure) {
        std::cerr << "FAILED: " << failure.reason << "\n";
        return 1;
    } catch (const std::exception& error) {
        std::cerr << "FAILED: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
