// SPDX-License-Identifier: MIT
// The daemon's per-frame path does not allocate: PointerDaemon::run() itself, with a rendered
// clip replayed as a YUYV camera (--realtime's source), the null sink and a control socket,
// counted by the replaced global operator new of tests/support/allocation_counter.cpp. Counting
// starts once the pointer moves (set-up done: the tracker's first target sized its buffers) and
// stops when the source reports the end, so it covers the loop's waits, the signal and control
// checks, the core, the pointer, the sink and the statistics, frame after frame.

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "allocation_counter.hpp"
#include "raypoint/control/control_socket.hpp"
#include "raypoint/loop/pointer_daemon.hpp"
#include "raypoint/loop/realtime_source.hpp"
#include "raypoint/output/event_sink.hpp"
#include "raypoint/scene/presets.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {
namespace {

// What the two wrappers below share: moves seen by the sink, and the count.
struct Probe {
    int moves = 0;
    bool counting = false;
    int counted_frames = 0;
    long allocations = -1;
};

// Passes everything through to the real source; counts from the first frame after the pointer
// has moved a few times (the tracker in steady tracking: its estimators size their buffers on
// their first target) until the source ends.
class CountingSource final : public FrameSource {
  public:
    CountingSource(std::unique_ptr<FrameSource> inner, Probe& probe)
        : inner_(std::move(inner)), probe_(probe) {}

    Capture next(int timeout_ms) override {
        if (!probe_.counting && probe_.allocations < 0 && probe_.moves >= 3) {
            probe_.counting = true;
            test::start_counting_allocations();
        }
        Capture capture = inner_->next(timeout_ms);
        if (capture.status == CaptureStatus::ended && probe_.counting) {
            probe_.allocations = test::stop_counting_allocations();
            probe_.counting = false;
        }
        if (capture.status == CaptureStatus::frame) {
            ++frames_;
            if (probe_.counting) ++probe_.counted_frames;
        }
        return capture;
    }
    int wait_fd() const noexcept override { return inner_->wait_fd(); }
    void release() noexcept override { inner_->release(); }
    bool reopen() override { return inner_->reopen(); }
    const std::string& last_error() const noexcept override { return inner_->last_error(); }
    std::string description() const override { return inner_->description(); }

    int frames() const noexcept { return frames_; }

  private:
    std::unique_ptr<FrameSource> inner_;
    Probe& probe_;
    int frames_ = 0;
};

// Counts the commands that moved the pointer, then drops them as NullSink does.
class MotionCountingSink final : public EventSink {
  public:
    explicit MotionCountingSink(Probe& probe) : probe_(probe) {}
    void emit(const core::PointerCommand& command, core::Timestamp) noexcept override {
        if (command.dx != 0 || command.dy != 0) ++probe_.moves;
    }
    void release_all(core::Timestamp) noexcept override {}
    std::string_view name() const override { return "null (counting moves)"; }

  private:
    Probe& probe_;
};

TEST(DaemonNoAllocation, FrameLoopWithTheNullSink) {
    unsetenv("NOTIFY_SOCKET");  // no systemd: its STATUS= lines are not part of this
    // The ideal scene, smaller and faster: the sphere enters at 0.3 s and moves for 1.2 s.
    scene::SceneSpec spec = scene::preset("ideal");
    spec.width = 320;
    spec.height = 240;
    spec.fps = 60;
    spec.seconds = 4.0;
    const scene::Renderer renderer(spec);
    YuyvClip clip({spec.width, spec.height}, spec.fps);
    for (int i = 0; i < renderer.frame_count(); ++i)
        clip.append(renderer.render(i).bgr);

    Probe probe;
    auto realtime = std::make_unique<RealtimeSource>(std::move(clip), "ideal", false);
    const RealtimeSource& replay = *realtime;
    auto source = std::make_unique<CountingSource>(std::move(realtime), probe);
    const CountingSource& counted = *source;
    const std::filesystem::path socket =
        std::filesystem::temp_directory_path() /
        ("raypoint-test-loop-" + std::to_string(getpid()) + ".sock");

    DaemonParts parts;
    parts.source = std::move(source);
    parts.sink = std::make_unique<MotionCountingSink>(probe);
    parts.control = std::make_unique<ControlServer>(socket.string());
    parts.exit_when_lost = true;
    PointerDaemon daemon(std::move(parts));
    EXPECT_EQ(daemon.run(), 0);

    // Every frame came, or was dropped as a camera drops them for a loop that fell behind (a
    // busy machine).
    EXPECT_EQ(counted.frames() + replay.dropped(), renderer.frame_count());
    // The sphere was tracked through the counted frames: they did the whole work.
    EXPECT_GE(probe.counted_frames, 30);
    EXPECT_GE(probe.moves, 10);
    EXPECT_EQ(probe.allocations, 0);
}

}  // namespace
}  // namespace raypoint::daemon
