// SPDX-License-Identifier: MIT
#include "raypoint/loop/realtime_source.hpp"

#include <poll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "raypoint/loop/run_statistics.hpp"

namespace raypoint::daemon {
namespace {

// A camera with four buffers (v4l2_camera.cpp) has one lent to the loop and three to fill.
constexpr std::int64_t waiting_limit = 3;

}  // namespace

RealtimeSource::RealtimeSource(YuyvClip clip, std::string label, bool loop)
    : RealtimeSource(std::variant<YuyvClip, MjpegClip>(std::move(clip)), std::move(label), loop) {}

RealtimeSource::RealtimeSource(MjpegClip clip, std::string label, bool loop)
    : RealtimeSource(std::variant<YuyvClip, MjpegClip>(std::move(clip)), std::move(label), loop) {}

RealtimeSource::RealtimeSource(std::variant<YuyvClip, MjpegClip> clip, std::string label, bool loop)
    : clip_(std::move(clip)), label_(std::move(label)), loop_(loop) {
    if (frame_count() == 0) throw std::invalid_argument(label_ + ": the clip has no frames");
    timer_fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (timer_fd_ < 0) {
        throw std::runtime_error(std::string("timerfd_create(CLOCK_MONOTONIC): ") +
                                 std::strerror(errno) +
                                 " (--realtime needs timerfd, Linux 2.6.25)");
    }
    arm(monotonic_now_us());  // the first frame is due at once
}

RealtimeSource::~RealtimeSource() {
    if (timer_fd_ >= 0) close(timer_fd_);
}

double RealtimeSource::fps() const noexcept {
    return on_clip([](const auto& clip) { return clip.fps(); });
}

int RealtimeSource::frame_count() const noexcept {
    return on_clip([](const auto& clip) { return clip.frame_count(); });
}

core::Timestamp RealtimeSource::due(std::int64_t serial) const noexcept {
    return start_ + core::seconds_to_us(static_cast<double>(serial) / fps());
}

void RealtimeSource::arm(core::Timestamp when) noexcept {
    itimerspec at{};
    at.it_value.tv_sec = static_cast<time_t>(when / 1'000'000);
    at.it_value.tv_nsec = static_cast<long>(when % 1'000'000) * 1000;
    // Cannot fail with a valid descriptor and value; a past instant expires at once.
    (void)timerfd_settime(timer_fd_, TFD_TIMER_ABSTIME, &at, nullptr);
}

void RealtimeSource::clear_timer() noexcept {
    std::uint64_t expirations = 0;
    // EAGAIN: the timer has not fired (a frame already due was taken without it), so there is
    // nothing to clear. A signal may interrupt the read; nothing else can fail on our timerfd.
    while (read(timer_fd_, &expirations, sizeof expirations) < 0 && errno == EINTR) {
    }
}

Capture RealtimeSource::next(int timeout_ms) {
    if (finished_) return end_of_input_capture();
    Capture capture;
    core::Timestamp now = monotonic_now_us();
    // A frame already due (the loop is behind) is taken without asking the timer, which may
    // not have fired yet for an instant in the past.
    if (start_ < 0 || due(serial_) > now) {
        pollfd timer{timer_fd_, POLLIN, 0};
        if (poll(&timer, 1, timeout_ms) <= 0) return capture;  // timeout (or EINTR: asked again)
        now = monotonic_now_us();
    }
    clear_timer();
    if (start_ < 0) start_ = now;
    // The newest frame due by now; with more than `waiting_limit` waiting, the older ones were
    // overwritten, as in a camera's full buffer queue.
    const auto newest =
        static_cast<std::int64_t>(std::floor(static_cast<double>(now - start_) * fps() / 1e6));
    if (newest - serial_ >= waiting_limit) {
        dropped_ += newest - waiting_limit + 1 - serial_;
        serial_ = newest - waiting_limit + 1;
    }
    if (!loop_ && serial_ >= frame_count()) {
        finished_ = true;
        return end_of_input_capture();
    }
    const core::Timestamp when = due(serial_);
    if (when > now) {  // woken before the frame was due (a clock step): wait for it
        arm(when);
        return capture;
    }
    const int index = static_cast<int>(serial_ % frame_count());
    capture.frame = on_clip([&](auto& clip) { return clip.view(index, when); });
    ++serial_;
    arm(due(serial_));                    // also after the last frame: then next() says ended
    if (capture.frame.data == nullptr) {  // an MJPEG frame that does not decode: skipped
        ++dropped_;
        return Capture{};
    }
    capture.ready = when;
    capture.status = CaptureStatus::frame;
    ++delivered_;
    return capture;
}

std::string RealtimeSource::description() const {
    const std::size_t bytes = on_clip([](const auto& clip) { return clip.memory_bytes(); });
    const cv::Size size = on_clip([](const auto& clip) { return clip.size(); });
    const double megabytes = static_cast<double>(bytes) / (1024.0 * 1024.0);
    char decoded[64] = "";
    if (const auto* mjpeg = std::get_if<MjpegClip>(&clip_)) {
        std::snprintf(decoded, sizeof decoded, ", decoded at %d/8 scale as a camera's",
                      mjpeg->scale_eighths());
    }
    char text[320];
    std::snprintf(text, sizeof text,
                  " (replayed in real time as %s %dx%d%s at %.2f fps, %d frames%s; %.1f MiB of "
                  "frames held in memory, not a camera's cost; %lld delivered, %lld dropped)",
                  decoded[0] != '\0' ? "MJPEG" : "YUYV", size.width, size.height, decoded, fps(),
                  frame_count(), loop_ ? ", looped" : "", megabytes,
                  static_cast<long long>(delivered_), static_cast<long long>(dropped_));
    return label_ + text;
}

}  // namespace raypoint::daemon
