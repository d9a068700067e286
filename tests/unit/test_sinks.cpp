// SPDX-License-Identifier: MIT
// The pointer's outputs without a kernel: the command-to-events encoding that the uinput device
// and the file sink share, the file sink's text, and --sink.

#include <linux/input-event-codes.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/cli/sink_option.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/file_sink.hpp"
#include "raypoint/output/pointer_events.hpp"
#include "raypoint/output/uinput_pointer.hpp"

namespace raypoint::daemon {
namespace {

using core::Button;
using core::PointerCommand;
using Events = std::vector<EvdevEvent>;

constexpr DeviceProfile relative{core::PointerMode::relative, 65535};
constexpr DeviceProfile absolute{core::PointerMode::absolute, 1000};

constexpr EvdevEvent syn{EV_SYN, SYN_REPORT, 0};

Events events(const EventBatch& batch) {
    return {batch.events().begin(), batch.events().end()};
}

PointerCommand move(int dx, int dy) {
    PointerCommand command;
    command.dx = dx;
    command.dy = dy;
    return command;
}

PointerCommand place(int x, int y) {
    PointerCommand command;
    command.has_absolute = true;
    command.abs_x = x;
    command.abs_y = y;
    return command;
}

PointerCommand change(Button button, bool pressed) {
    PointerCommand command;
    command.add(button, pressed);
    return command;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::filesystem::path temp_path(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("raypoint-test-sinks-" + std::to_string(::getpid()) + "-" + name);
}

TEST(PointerEncoder, RelativeMoveIsOneReport) {
    PointerEncoder encoder(relative);
    EXPECT_EQ(events(encoder.encode(move(5, -3))),
              (Events{{EV_REL, REL_X, 5}, {EV_REL, REL_Y, -3}, syn}));
}

TEST(PointerEncoder, RelativeDropsZeroAxesAndEmptyReports) {
    // The kernel drops a zero REL value and a SYN_REPORT with nothing before it.
    PointerEncoder encoder(relative);
    EXPECT_EQ(events(encoder.encode(move(0, 7))), (Events{{EV_REL, REL_Y, 7}, syn}));
    EXPECT_TRUE(encoder.encode(PointerCommand{}).empty());
}

TEST(PointerEncoder, RelativeIgnoresAbsolutePositions) {
    PointerEncoder encoder(relative);
    EXPECT_TRUE(encoder.encode(place(10, 20)).empty());
}

TEST(PointerEncoder, AbsoluteMoveSendsChangedAxesOnly) {
    PointerEncoder encoder(absolute);
    EXPECT_EQ(events(encoder.encode(place(100, 200))),
              (Events{{EV_ABS, ABS_X, 100}, {EV_ABS, ABS_Y, 200}, syn}));
    // The same place again: the kernel would drop both values, so nothing at all.
    EXPECT_TRUE(encoder.encode(place(100, 200)).empty());
    EXPECT_EQ(events(encoder.encode(place(100, 250))), (Events{{EV_ABS, ABS_Y, 250}, syn}));
}

TEST(PointerEncoder, AbsoluteStartsAtZeroAndClampsToRange) {
    PointerEncoder encoder(absolute);
    EXPECT_EQ(events(encoder.encode(place(0, 5000))), (Events{{EV_ABS, ABS_Y, 1000}, syn}));
    EXPECT_EQ(events(encoder.encode(place(-4, 1000))), Events{});
}

TEST(PointerEncoder, AbsoluteIgnoresRelativeMotion) {
    PointerEncoder encoder(absolute);
    EXPECT_TRUE(encoder.encode(move(3, 4)).empty());
}

TEST(PointerEncoder, PressAndReleaseEachGetAReport) {
    PointerEncoder encoder(relative);
    EXPECT_EQ(events(encoder.encode(change(Button::left, true))),
              (Events{{EV_KEY, BTN_LEFT, 1}, syn}));
    EXPECT_TRUE(encoder.is_down(Button::left));
    EXPECT_EQ(events(encoder.encode(change(Button::left, false))),
              (Events{{EV_KEY, BTN_LEFT, 0}, syn}));
    EXPECT_FALSE(encoder.is_down(Button::left));
}

// A device that refuses writes (uinput's EAGAIN when its buffer is full, ENODEV when it is
// gone): write_batch tells the encoder of each lost release, and the release goes out again.
struct FailingDevice {
    int fail_with = 0;
    Events written;
    int operator()(const EvdevEvent& event) {
        if (fail_with != 0) return -fail_with;
        written.push_back(event);
        return 0;
    }
};

class WriteFailures : public ::testing::TestWithParam<int> {};

TEST_P(WriteFailures, LostReleaseGoesOutWithTheNextBatch) {
    PointerEncoder encoder(relative);
    FailingDevice device;
    EXPECT_EQ(write_batch(encoder, encoder.encode(change(Button::left, true)), device), 0);
    device.fail_with = GetParam();
    EXPECT_EQ(write_batch(encoder, encoder.encode(change(Button::left, false)), device),
              GetParam());
    EXPECT_TRUE(encoder.is_down(Button::left)) << "the device still has it down";
    // Failing again: still pending.
    EXPECT_EQ(write_batch(encoder, encoder.encode(move(1, 0)), device), GetParam());
    EXPECT_TRUE(encoder.is_down(Button::left));
    device.fail_with = 0;
    device.written.clear();
    EXPECT_EQ(write_batch(encoder, encoder.encode(move(2, 0)), device), 0);
    EXPECT_EQ(device.written, (Events{{EV_REL, REL_X, 2}, syn, {EV_KEY, BTN_LEFT, 0}, syn}));
    EXPECT_FALSE(encoder.is_down(Button::left));
    // Sent once: nothing more to release.
    EXPECT_TRUE(encoder.release_all().empty());
}

TEST_P(WriteFailures, LostReleaseGoesOutWithReleaseAll) {
    PointerEncoder encoder(relative);
    FailingDevice device;
    write_batch(encoder, encoder.encode(change(Button::right, true)), device);
    device.fail_with = GetParam();
    write_batch(encoder, encoder.encode(change(Button::right, false)), device);
    device.fail_with = 0;
    device.written.clear();
    write_batch(encoder, encoder.release_all(), device);
    EXPECT_EQ(device.written, (Events{{EV_KEY, BTN_RIGHT, 0}, syn}));
    EXPECT_FALSE(encoder.is_down(Button::right));
}

// The pointer presses the button again before the retry: the device has it down already, so
// the press is dropped and no release is sent in between.
TEST_P(WriteFailures, PressAgainCancelsTheRetry) {
    PointerEncoder encoder(relative);
    FailingDevice device;
    write_batch(encoder, encoder.encode(change(Button::left, true)), device);
    device.fail_with = GetParam();
    write_batch(encoder, encoder.encode(change(Button::left, false)), device);
    device.fail_with = 0;
    device.written.clear();
    EXPECT_EQ(write_batch(encoder, encoder.encode(change(Button::left, true)), device), 0);
    EXPECT_TRUE(device.written.empty());
    EXPECT_TRUE(encoder.is_down(Button::left));
    EXPECT_EQ(events(encoder.release_all()), (Events{{EV_KEY, BTN_LEFT, 0}, syn}));
}

// A lost press changes nothing the desktop sees; the release that follows is harmless (the
// kernel drops a release of a key that is up) and the encoder counts the button up.
TEST_P(WriteFailures, LostPressIsNotRetried) {
    PointerEncoder encoder(relative);
    FailingDevice device;
    device.fail_with = GetParam();
    EXPECT_EQ(write_batch(encoder, encoder.encode(change(Button::left, true)), device), GetParam());
    device.fail_with = 0;
    EXPECT_EQ(write_batch(encoder, encoder.encode(change(Button::left, false)), device), 0);
    EXPECT_FALSE(encoder.is_down(Button::left));
    EXPECT_TRUE(encoder.encode(PointerCommand{}).empty());
}

INSTANTIATE_TEST_SUITE_P(Uinput, WriteFailures, ::testing::Values(EAGAIN, ENODEV),
                         [](const auto& param_info) {
                             return std::string(param_info.param == EAGAIN ? "EAGAIN" : "ENODEV");
                         });

TEST(PointerEncoder, ClickInOneCommandComesAfterTheMotion) {
    // A dwell click: the press and the release need a report between them.
    PointerEncoder encoder(relative);
    PointerCommand command = move(-2, 0);
    command.add(Button::right, true);
    command.add(Button::right, false);
    EXPECT_EQ(
        events(encoder.encode(command)),
        (Events{
            {EV_REL, REL_X, -2}, syn, {EV_KEY, BTN_RIGHT, 1}, syn, {EV_KEY, BTN_RIGHT, 0}, syn}));
}

TEST(PointerEncoder, RepeatedPressOrReleaseIsDropped) {
    // The kernel passes only key changes, so a second press would not reach a reader.
    PointerEncoder encoder(relative);
    EXPECT_TRUE(encoder.encode(change(Button::middle, false)).empty());
    encoder.encode(change(Button::middle, true));
    EXPECT_TRUE(encoder.encode(change(Button::middle, true)).empty());
}

TEST(PointerEncoder, WheelGoesWithTheMotion) {
    PointerEncoder relative_encoder(relative);
    PointerCommand command = move(1, 0);
    command.wheel = -2;
    EXPECT_EQ(events(relative_encoder.encode(command)),
              (Events{{EV_REL, REL_X, 1}, {EV_REL, REL_WHEEL, -2}, syn}));

    PointerEncoder absolute_encoder(absolute);
    PointerCommand scroll;
    scroll.wheel = 1;
    EXPECT_EQ(events(absolute_encoder.encode(scroll)), (Events{{EV_REL, REL_WHEEL, 1}, syn}));
}

TEST(PointerEncoder, HighResolutionWheelGoesInTheSameReport) {
    PointerEncoder encoder(relative);
    PointerCommand fine;  // a part of a detent: the hi-res axis alone
    fine.wheel_hi_res = 60;
    EXPECT_EQ(events(encoder.encode(fine)), (Events{{EV_REL, REL_WHEEL_HI_RES, 60}, syn}));
    PointerCommand whole;  // crossing a detent: both
    whole.wheel = -1;
    whole.wheel_hi_res = -150;
    EXPECT_EQ(events(encoder.encode(whole)),
              (Events{{EV_REL, REL_WHEEL, -1}, {EV_REL, REL_WHEEL_HI_RES, -150}, syn}));
}

TEST(PointerEncoder, ReleaseAllReleasesWhatIsDown) {
    PointerEncoder encoder(relative);
    PointerCommand command;
    command.add(Button::middle, true);
    command.add(Button::left, true);
    encoder.encode(command);
    EXPECT_EQ(events(encoder.release_all()),
              (Events{{EV_KEY, BTN_LEFT, 0}, syn, {EV_KEY, BTN_MIDDLE, 0}, syn}));
    EXPECT_FALSE(encoder.is_down(Button::left));
    EXPECT_FALSE(encoder.is_down(Button::middle));
    EXPECT_TRUE(encoder.release_all().empty());
}

TEST(PointerEncoder, FullestCommandFits) {
    PointerEncoder encoder(relative);
    // The right and middle buttons' releases were lost: both go out with the next command.
    encoder.release_failed(Button::right);
    encoder.release_failed(Button::middle);
    PointerCommand command = move(1, 1);
    command.wheel = 1;
    command.wheel_hi_res = 120;
    for (int i = 0; i < PointerCommand::max_changes; ++i)
        command.add(Button::left, i % 2 == 0);
    EXPECT_EQ(encoder.encode(command).size(), EventBatch::capacity);
}

TEST(FileSink, FormatsOneEventALine) {
    std::array<char, 64> buffer{};
    EXPECT_EQ(format_event({EV_KEY, BTN_LEFT, 1}, 5033333, buffer), "5033333 EV_KEY BTN_LEFT 1");
    EXPECT_EQ(format_event(syn, 0, buffer), "0 EV_SYN SYN_REPORT 0");
    EXPECT_EQ(format_event({EV_REL, REL_WHEEL_HI_RES, -60}, 9, buffer),
              "9 EV_REL REL_WHEEL_HI_RES -60");
    EXPECT_EQ(format_event({EV_REL, REL_X, -12}, 7, std::span<char>(buffer.data(), 8)), "");
}

TEST(FileSink, WritesExactlyTheDeviceEvents) {
    const std::filesystem::path path = temp_path("relative.txt");
    {
        FileSink sink(path, relative);
        EXPECT_EQ(sink.name(), "file:" + path.string());
        PointerCommand command = move(-12, 4);
        command.add(Button::left, true);
        sink.emit(command, 5033333);
        sink.emit(PointerCommand{}, 5066666);
        // Flushed per command: a reader sees the press before the sink goes away.
        EXPECT_EQ(read_file(path),
                  "5033333 EV_REL REL_X -12\n"
                  "5033333 EV_REL REL_Y 4\n"
                  "5033333 EV_SYN SYN_REPORT 0\n"
                  "5033333 EV_KEY BTN_LEFT 1\n"
                  "5033333 EV_SYN SYN_REPORT 0\n");
        sink.emit(change(Button::right, true), 5100000);
        sink.release_all(5133333);
        EXPECT_EQ(sink.last_error(), 0);
    }
    EXPECT_EQ(read_file(path),
              "5033333 EV_REL REL_X -12\n"
              "5033333 EV_REL REL_Y 4\n"
              "5033333 EV_SYN SYN_REPORT 0\n"
              "5033333 EV_KEY BTN_LEFT 1\n"
              "5033333 EV_SYN SYN_REPORT 0\n"
              "5100000 EV_KEY BTN_RIGHT 1\n"
              "5100000 EV_SYN SYN_REPORT 0\n"
              "5133333 EV_KEY BTN_LEFT 0\n"
              "5133333 EV_SYN SYN_REPORT 0\n"
              "5133333 EV_KEY BTN_RIGHT 0\n"
              "5133333 EV_SYN SYN_REPORT 0\n");
    std::filesystem::remove(path);
}

TEST(FileSink, ReleasesButtonsDownWhenDestroyed) {
    // As the kernel does when a uinput device is destroyed with a key down.
    const std::filesystem::path path = temp_path("absolute.txt");
    {
        FileSink sink(path, absolute);
        PointerCommand command = place(500, 400);
        command.add(Button::left, true);
        sink.emit(command, 1000);
    }
    EXPECT_EQ(read_file(path),
              "1000 EV_ABS ABS_X 500\n"
              "1000 EV_ABS ABS_Y 400\n"
              "1000 EV_SYN SYN_REPORT 0\n"
              "1000 EV_KEY BTN_LEFT 1\n"
              "1000 EV_SYN SYN_REPORT 0\n"
              "1000 EV_KEY BTN_LEFT 0\n"
              "1000 EV_SYN SYN_REPORT 0\n");
    std::filesystem::remove(path);
}

TEST(FileSink, UnwritablePathThrowsNamingIt) {
    const std::filesystem::path path = temp_path("no-such-dir") / "events.txt";
    try {
        FileSink sink(path, relative);
        FAIL() << "no exception";
    } catch (const OutputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
}

TEST(SinkFactory, ParsesTheThreeForms) {
    EXPECT_EQ(parse_sink_spec("uinput").kind, SinkKind::uinput);
    EXPECT_EQ(parse_sink_spec("null").kind, SinkKind::null);
    const SinkSpec file = parse_sink_spec("file:/tmp/a b.txt");
    EXPECT_EQ(file.kind, SinkKind::file);
    EXPECT_EQ(file.path, std::filesystem::path("/tmp/a b.txt"));
}

TEST(SinkFactory, UnknownSinkListsTheAllowedOnes) {
    for (const char* value : {"foo", "", "file:", "Uinput", "file"}) {
        try {
            parse_sink_spec(value);
            FAIL() << "accepted --sink " << value;
        } catch (const UsageError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("--sink"), std::string::npos) << message;
            EXPECT_NE(message.find("file:"), std::string::npos) << message;
        }
    }
    try {
        parse_sink_spec("foo");
    } catch (const UsageError& error) {
        EXPECT_STREQ(error.what(), "--sink foo: unknown sink; use uinput, file:PATH or null");
    }
}

TEST(SinkFactory, MakesNullAndFileSinks) {
    EXPECT_EQ(make_sink(parse_sink_spec("null"), relative)->name(), "null");
    const std::filesystem::path path = temp_path("factory.txt");
    EXPECT_EQ(make_sink(SinkSpec{SinkKind::file, path}, relative)->name(), "file:" + path.string());
    std::filesystem::remove(path);
}

TEST(UinputError, SaysWhatToDo) {
    const std::string denied = UinputError("libevdev_uinput_create_from_device", EACCES).what();
    EXPECT_EQ(denied,
              "libevdev_uinput_create_from_device on /dev/uinput: Permission denied; add the udev "
              "rule packaging/70-raypoint-uinput.rules (TAG+=\"uaccess\") or join the group that "
              "owns /dev/uinput");
    const std::string missing = UinputError("libevdev_uinput_create_from_device", ENOENT).what();
    EXPECT_EQ(missing,
              "libevdev_uinput_create_from_device on /dev/uinput: No such file or directory; load "
              "the module: sudo modprobe uinput (packaging installs modules-load.d/raypoint.conf)");
    EXPECT_EQ(UinputError("libevdev_new", ENOMEM).error(), ENOMEM);
}

}  // namespace
}  // namespace raypoint::daemon
