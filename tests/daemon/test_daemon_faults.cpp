// SPDX-License-Identifier: MIT
// The daemon under faults, through its seams (FrameSource, EventSink), each with one contract:
// no crash, no click the user did not make, no button left pressed, the state reported (ctl
// status), and recovery when the fault ends. Rendered clips (320x240, 30 fps) run through
// PointerDaemon::run() as fast as it takes them; docs/reliability.md lists the outcomes.
//   click: the hand moves right 4.0-5.5 s, pushes once at 6.0-6.7 s, moves down 7.5-9.0 s
//   drag:  the hand pushes at 4.0 s, moves right 5.3-6.5 s while pushed, pulls back at 6.8 s

#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "fault_harness.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/control/control_socket.hpp"
#include "raypoint/loop/pointer_daemon.hpp"

namespace raypoint::daemon::test {
namespace {

constexpr core::Timestamp seconds(double s) {
    return core::seconds_to_us(s);
}
int frame_at(double s) {
    return static_cast<int>(seconds(s) / frame_interval_us);
}

// `ctl status` asked from inside the loop's own thread: the request goes out before a frame
// (connect and send do not wait for the daemon), the daemon answers on its next pass, and the
// reply is read before a later frame.
class StatusProbe {
  public:
    explicit StatusProbe(std::string path) : path_(std::move(path)) {}
    ~StatusProbe() {
        if (fd_ >= 0) close(fd_);
    }
    void ask() {
        fd_ = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::snprintf(address.sun_path, sizeof address.sun_path, "%s", path_.c_str());
        ASSERT_EQ(connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
        ASSERT_EQ(send(fd_, "status\n", 7, MSG_NOSIGNAL), 7);
    }
    // What has arrived so far, without waiting.
    void collect() {
        if (fd_ < 0) return;
        char buffer[4096];
        pollfd waiting{fd_, POLLIN, 0};
        while (poll(&waiting, 1, 0) == 1) {
            const ssize_t got = read(fd_, buffer, sizeof buffer);
            if (got <= 0) {
                close(fd_);
                fd_ = -1;
                return;
            }
            reply.append(buffer, static_cast<std::size_t>(got));
        }
    }
    std::string reply;

  private:
    std::string path_;
    int fd_ = -1;
};

std::string socket_path(const char* name) {
    return (std::filesystem::temp_directory_path() /
            ("raypoint-fault-" + std::to_string(getpid()) + "-" + name + ".sock"))
        .string();
}

struct DaemonRun {
    int exit_code = -1;
    std::string status;  // the probe's reply
};

// Runs the clip with `script`; `hook` sees each frame index before it is delivered (with the
// source, the sink and the probe), as a camera, a device or a user would act at that moment.
template <class Hook>
DaemonRun run_daemon(const std::string& preset, std::vector<FaultWindow> script,
                     DeviceModelSink& sink, Hook hook, std::function<config::Config()> reload = {},
                     int loops = 1, int failed_reopens = 1) {
    unsetenv("NOTIFY_SOCKET");
    const std::string path = socket_path(preset.c_str());
    auto source = std::make_unique<ScriptedSource>(rendered_clip(preset), std::move(script), loops);
    ScriptedSource& scripted = *source;
    scripted.failed_reopens = failed_reopens;
    StatusProbe probe(path);
    scripted.before_frame = [&](int index) { hook(index, probe); };
    struct ForwardingSink final : EventSink {
        explicit ForwardingSink(DeviceModelSink& to) : to_(to) {}
        void emit(const core::PointerCommand& c, core::Timestamp t) noexcept override {
            to_.emit(c, t);
        }
        void release_all(core::Timestamp t) noexcept override { to_.release_all(t); }
        std::string_view name() const override { return to_.name(); }
        int last_error() const noexcept override { return to_.last_error(); }
        long long failed_writes() const noexcept override { return to_.failed_writes(); }
        DeviceModelSink& to_;
    };
    DaemonParts parts;
    parts.config.core.pointer.motion.mirror = false;
    parts.source = std::move(source);
    parts.sink = std::make_unique<ForwardingSink>(sink);
    parts.control = std::make_unique<ControlServer>(path);
    parts.reload = std::move(reload);
    DaemonRun run;
    {
        PointerDaemon daemon(std::move(parts));
        run.exit_code = daemon.run();
    }
    probe.collect();
    run.status = probe.reply;
    return run;
}

int presses_between(const DeviceModelSink& sink, core::Timestamp from, core::Timestamp to) {
    int count = 0;
    for (const KeyEvent& key : sink.keys()) {
        if (key.pressed && key.at >= from && key.at <= to) ++count;
    }
    return count;
}

int presses(const DeviceModelSink& sink) {
    return presses_between(sink, 0, seconds(1e6));
}

TEST(DaemonFaults, NoFaultClickClipClicksOnce) {
    DeviceModelSink sink;
    const DaemonRun run = run_daemon("click", {}, sink, [](int, StatusProbe&) {});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(presses(sink), 1);
    EXPECT_EQ(presses_between(sink, seconds(6.0), seconds(7.3)), 1);
    EXPECT_FALSE(sink.any_down());
    EXPECT_GT(sink.motion_since(seconds(7.5)), 0);
}

// A camera fault while the hand moves right (4.3-4.9 s): no press during it, nothing held at the
// end, `ctl status` answers during it, and the pointer moves again after it.
struct FrameFaultCase {
    Fault fault;
    const char* name;
};

class FrameFaults : public ::testing::TestWithParam<FrameFaultCase> {};

TEST_P(FrameFaults, NoClickNothingHeldStateReportedRecovers) {
    const FrameFaultCase c = GetParam();
    const int first = frame_at(4.3);
    const int last = frame_at(4.9);
    DeviceModelSink sink;
    const DaemonRun run =
        run_daemon("click", {{c.fault, first, last}}, sink, [&](int index, StatusProbe& probe) {
            if (index == first) probe.ask();
            if (index > first) probe.collect();
        });
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(presses_between(sink, seconds(4.3), seconds(5.0)), 0) << c.name;
    EXPECT_LE(presses(sink), 1) << c.name << ": at most the clip's own click";
    EXPECT_FALSE(sink.any_down()) << c.name;
    EXPECT_NE(run.status.find("state: "), std::string::npos) << c.name << ": " << run.status;
    if (c.fault == Fault::capture_error) {
        EXPECT_NE(run.status.find("waiting for a camera (VIDIOC_DQBUF: No such device)"),
                  std::string::npos)
            << run.status;
        EXPECT_NE(run.status.find("camera losses: 1"), std::string::npos) << run.status;
    }
    EXPECT_GT(sink.motion_since(seconds(7.5)), 0) << c.name << ": the pointer moves again";
}

INSTANTIATE_TEST_SUITE_P(Camera, FrameFaults,
                         ::testing::Values(FrameFaultCase{Fault::black, "black"},
                                           FrameFaultCase{Fault::saturated, "saturated"},
                                           FrameFaultCase{Fault::frozen, "frozen"},
                                           FrameFaultCase{Fault::flicker, "flicker"},
                                           FrameFaultCase{Fault::capture_error, "capture error"}),
                         [](const auto& param_info) {
                             std::string name = param_info.param.name;
                             for (char& ch : name) {
                                 if (ch == ' ') ch = '_';
                             }
                             return name;
                         });

// The device refuses writes (EAGAIN: its buffer is full; ENODEV: it is gone) from before the
// drag's release (6.9 s) to 7.5 s: the release is lost, sent again each frame, and taken once
// the device takes writes again. Nothing is held at the end; status says what failed.
class OutputFaults : public ::testing::TestWithParam<int> {};

TEST_P(OutputFaults, LostReleaseIsSentAgainWhenWritesWork) {
    const int error = GetParam();
    DeviceModelSink sink;
    const int first = frame_at(6.5);
    const int last = frame_at(7.5);
    const DaemonRun run = run_daemon("drag", {}, sink, [&](int index, StatusProbe& probe) {
        sink.fail_with = index >= first && index <= last ? error : 0;
        if (index == last) probe.ask();
        if (index > last) probe.collect();
    });
    EXPECT_EQ(run.exit_code, 0);
    ASSERT_EQ(presses(sink), 1) << "the drag's press, before the failures";
    ASSERT_EQ(sink.keys().size(), 2U);
    const KeyEvent& release = sink.keys().back();
    EXPECT_FALSE(release.pressed);
    // Taken on the first frame the device accepts writes again.
    EXPECT_EQ(release.at, (last + 1) * frame_interval_us);
    EXPECT_FALSE(sink.any_down());
    EXPECT_GT(sink.failed_writes(), 0);
    EXPECT_NE(run.status.find("output errors: "), std::string::npos) << run.status;
    EXPECT_EQ(run.status.find("output errors: 0\n"), std::string::npos) << run.status;
    EXPECT_NE(run.status.find(std::string("(last: ") + std::strerror(error) + ")"),
              std::string::npos)
        << run.status;
}

// A press the device refused never reached the desktop: the later release is a no-op there, and
// nothing is held.
TEST_P(OutputFaults, LostPressLeavesNothingHeld) {
    const int error = GetParam();
    DeviceModelSink sink;
    const DaemonRun run = run_daemon("drag", {}, sink, [&](int index, StatusProbe&) {
        sink.fail_with = index >= frame_at(3.9) && index <= frame_at(5.0) ? error : 0;
    });
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(presses(sink), 0);
    EXPECT_FALSE(sink.any_down());
}

INSTANTIATE_TEST_SUITE_P(Uinput, OutputFaults, ::testing::Values(EAGAIN, ENODEV),
                         [](const auto& param_info) {
                             return std::string(param_info.param == EAGAIN ? "EAGAIN" : "ENODEV");
                         });

// SIGINT, SIGTERM and SIGHUP in three states: INITIALIZING (0.3 s), mid-drag with the button
// down (5.5 s), and with the camera lost. Stop signals end the run with the button released;
// SIGHUP reloads, which releases it and starts the tracker afresh (no click for its start-up).
struct SignalCase {
    int signal;
    double at;         // clip seconds
    bool camera_lost;  // the camera is away when it comes
    const char* name;
};

class Signals : public ::testing::TestWithParam<SignalCase> {};

TEST_P(Signals, ButtonsReleasedAndStateKept) {
    const SignalCase c = GetParam();
    const int at = frame_at(c.at);
    std::vector<FaultWindow> script;
    if (c.camera_lost) script.push_back({Fault::capture_error, at, at + 15});
    DeviceModelSink sink;
    bool down_when_sent = false;
    int reloads = 0;
    const DaemonRun run = run_daemon(
        "drag", script, sink,
        [&](int index, StatusProbe&) {
            if (index != (c.camera_lost ? at + 16 : at)) return;
            down_when_sent = sink.any_down();
            raise(c.signal);  // blocked in this thread: read from the signalfd
        },
        [&] {
            ++reloads;
            return config::Config{};
        });
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_FALSE(sink.any_down());
    if (c.at > 5.0 && !c.camera_lost) {
        EXPECT_TRUE(down_when_sent) << "mid-drag: the button down";
    }
    if (c.signal == SIGHUP) {
        EXPECT_EQ(reloads, 1);
        // The fresh tracker needs its start-up (2 s) before it finds the hand again.
        EXPECT_EQ(presses_between(sink, (at + 1) * frame_interval_us,
                                  (at + 1) * frame_interval_us + seconds(2.0)),
                  0);
    } else {
        // Stopped at that frame: nothing after it.
        for (const KeyEvent& key : sink.keys()) {
            EXPECT_LE(key.at, (at + (c.camera_lost ? 16 : 0)) * frame_interval_us);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Daemon, Signals,
                         ::testing::Values(SignalCase{SIGTERM, 0.3, false, "SIGTERM_initializing"},
                                           SignalCase{SIGTERM, 5.5, false, "SIGTERM_mid_drag"},
                                           SignalCase{SIGTERM, 5.0, true, "SIGTERM_camera_lost"},
                                           SignalCase{SIGINT, 0.3, false, "SIGINT_initializing"},
                                           SignalCase{SIGINT, 5.5, false, "SIGINT_mid_drag"},
                                           SignalCase{SIGINT, 5.0, true, "SIGINT_camera_lost"},
                                           SignalCase{SIGHUP, 0.3, false, "SIGHUP_initializing"},
                                           SignalCase{SIGHUP, 5.5, false, "SIGHUP_mid_drag"},
                                           SignalCase{SIGHUP, 5.0, true, "SIGHUP_camera_lost"}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// 20 unplug/replug cycles in one run, each while the drag holds the button (5.5 s of each loop
// of `drag`): each loss releases the button, every press has its release, the camera comes back
// every time, and the drags after the last one still click.
TEST(DaemonFaults, TwentyUnplugCyclesMidDrag) {
    constexpr int cycles = 20;
    const int per_loop = static_cast<int>(rendered_clip("drag").size());
    std::vector<FaultWindow> script;
    for (int i = 0; i < cycles; ++i) {
        const int at = i * per_loop + frame_at(5.5);
        script.push_back({Fault::capture_error, at, at + 10});
    }
    DeviceModelSink sink;
    int down_at_unplug = 0;
    const DaemonRun run = run_daemon(
        "drag", script, sink,
        [&](int index, StatusProbe& probe) {
            if (index % per_loop == frame_at(5.5) && sink.any_down()) ++down_at_unplug;
            if (index == (cycles + 1) * per_loop - 10) probe.ask();
            if (index > (cycles + 1) * per_loop - 10) probe.collect();
        },
        {}, cycles + 1, 0);
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_GE(down_at_unplug, cycles - 2) << "the button was down at (nearly) every unplug";
    long long presses = 0;
    long long releases = 0;
    for (const KeyEvent& key : sink.keys())
        ++(key.pressed ? presses : releases);
    EXPECT_EQ(presses, releases);
    EXPECT_GE(presses, cycles);
    EXPECT_FALSE(sink.any_down());
    EXPECT_NE(run.status.find("camera losses: 20\n"), std::string::npos) << run.status;
    // The last loop, with no unplug, drags as the first would: one press and its release.
    EXPECT_EQ(presses_between(sink, cycles * per_loop * frame_interval_us,
                              (cycles + 1) * per_loop * frame_interval_us),
              1);
}

// The INI made invalid (or deleted) while running: SIGHUP's reload throws, the running
// configuration stays, and the drag goes on to its own release.
TEST(DaemonFaults, InvalidIniOnReloadKeepsTheRunningConfiguration) {
    DeviceModelSink sink;
    int reloads = 0;
    const DaemonRun run = run_daemon(
        "drag", {}, sink,
        [&](int index, StatusProbe&) {
            if (index == frame_at(5.5)) raise(SIGHUP);
        },
        [&]() -> config::Config {
            ++reloads;
            throw config::InvalidConfig({"raypoint.ini: cannot open: No such file or directory"});
        });
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(reloads, 1);
    ASSERT_EQ(sink.keys().size(), 2U) << "the drag's one press and its release";
    EXPECT_GE(sink.keys().back().at, seconds(6.5)) << "released by the pull-back, not the reload";
    EXPECT_FALSE(sink.any_down());
}

}  // namespace
}  // namespace raypoint::daemon::test
