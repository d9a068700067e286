// SPDX-License-Identifier: MIT
// The core as the daemon drives it, on frames and timestamps no camera should send: any size from
// 1x1 to 640x480, BGR or YUYV, rows padded to odd strides; constant, saturated, black, noise,
// a bright disc (so the tracker reaches TRACKING and its estimators run), the same frame again,
// flicker, raw bytes; timestamps equal, backwards, a microsecond apart or an hour. Settings come
// from `--set` lines. Every frame: no crash, finite features and position, and the pointer's
// buttons exactly as its commands said; after release_all() no button is down.
//
// Input: `--set` lines, a NUL, 4 header bytes (width, height, format, row padding), then 4 bytes
// a frame (content, x, y, parameter). Timestamps stay within [0, 2^62): a CLOCK_MONOTONIC time in
// microseconds, whose differences cannot overflow.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

#include "fuzz_target.hpp"
#include "raypoint/config/config.hpp"
#include "raypoint/config/schema.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/core/tracker.hpp"

namespace {

using raypoint::core::Timestamp;

constexpr std::size_t max_frames = 120;
constexpr Timestamp max_timestamp = Timestamp{1} << 62;

[[noreturn]] void fail(const char* what, std::size_t frame) {
    std::fprintf(stderr, "frame %zu: %s\n", frame, what);
    std::abort();
}

raypoint::config::Config settings_from(std::string_view lines) {
    using namespace raypoint::config;
    Config config;
    apply_preset(config, "default");
    while (!lines.empty()) {
        const auto newline = lines.find('\n');
        const std::string_view line = lines.substr(0, newline);
        lines = newline == std::string_view::npos ? std::string_view() : lines.substr(newline + 1);
        try {
            apply_assignment(config, line);
        } catch (const ConfigError&) {
        }
    }
    // What the daemon would refuse to start with never reaches the core.
    if (!cross_check(config).empty()) apply_preset(config, "default");
    return config;
}

// A frame's pixels in the source format, padding included.
class Painter {
  public:
    Painter(int width, int height, int stride, raypoint::core::PixelFormat format)
        : width_(width),
          height_(height),
          stride_(stride),
          format_(format),
          pixels_(static_cast<std::size_t>(stride) * static_cast<std::size_t>(height)) {}

    const std::uint8_t* data() const noexcept { return pixels_.data(); }

    // grey(x, y) for every pixel; YUYV gets it as luma with neutral chroma.
    template <class Grey>
    void paint(Grey grey) {
        for (int y = 0; y < height_; ++y) {
            std::uint8_t* row = pixels_.data() + static_cast<std::size_t>(y) * stride_;
            for (int x = 0; x < width_; ++x) {
                const std::uint8_t value = grey(x, y);
                if (format_ == raypoint::core::PixelFormat::bgr) {
                    row[3 * x] = value;
                    row[3 * x + 1] = static_cast<std::uint8_t>(value / 2);
                    row[3 * x + 2] = value;
                } else {
                    row[2 * x] = value;
                    row[2 * x + 1] = 128;
                }
            }
        }
    }
    void invert() {
        for (auto& byte : pixels_)
            byte = static_cast<std::uint8_t>(255 - byte);
    }
    void raw(std::span<const std::uint8_t> bytes) {
        if (bytes.empty()) return;
        for (std::size_t i = 0; i < pixels_.size(); ++i)
            pixels_[i] = bytes[i % bytes.size()];
    }

  private:
    int width_;
    int height_;
    int stride_;
    raypoint::core::PixelFormat format_;
    std::vector<std::uint8_t> pixels_;
};

Timestamp next_time(Timestamp now, int op, std::uint8_t parameter) {
    Timestamp next = now;
    switch (op) {
        case 0:
            next = now + 33'333;
            break;
        case 1:
            break;  // the same timestamp again
        case 2:
            next = now - Timestamp{parameter} * 10'000;
            break;
        case 3:
            next = now + Timestamp{3600} * 1'000'000;
            break;
        case 4:
            next = now + 1;
            break;
        case 5:
            next = now + Timestamp{parameter} * 1'000;
            break;
        case 6:
            next = Timestamp{parameter} << 54;
            break;
        default:
            next = now + 16'667;
            break;
    }
    return std::clamp<Timestamp>(next, 0, max_timestamp - 1);
}

bool finite(cv::Point2d p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raypoint;
    const std::uint8_t* end = data + size;
    const std::uint8_t* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
    if (nul == nullptr || end - nul < 5) return 0;
    const config::Config config =
        settings_from(std::string_view(reinterpret_cast<const char*>(data), nul - data));
    const std::uint8_t* header = nul + 1;
    core::FrameView frame;
    frame.format = (header[3] & 1) != 0 ? core::PixelFormat::yuyv : core::PixelFormat::bgr;
    frame.width = 1 + (header[0] | ((header[2] & 0x03) << 8)) % 640;
    frame.height = 1 + (header[1] | ((header[2] & 0x0c) << 6)) % 480;
    // YUYV carries pixels in pairs: V4L2 gives no odd width (core/frame.hpp's precondition).
    if (frame.format == core::PixelFormat::yuyv && frame.width % 2 != 0) ++frame.width;
    const int bytes_per_pixel = frame.format == core::PixelFormat::bgr ? 3 : 2;
    frame.stride = frame.width * bytes_per_pixel + (header[3] >> 1);
    Painter painter(frame.width, frame.height, frame.stride, frame.format);
    frame.data = painter.data();

    core::Tracker tracker(config.core);
    core::PointerController pointer(
        config.core.pointer, static_cast<double>(frame.width) / static_cast<double>(frame.height));
    std::array<bool, 3> down{};
    const auto apply = [&](const core::PointerCommand& command, std::size_t index) {
        for (const auto& change : command.button_changes())
            down[static_cast<std::size_t>(change.button)] = change.pressed;
        for (const auto button : {core::Button::left, core::Button::right, core::Button::middle}) {
            if (pointer.is_down(button) != down[static_cast<std::size_t>(button)]) {
                fail("a button's state differs from the commands sent", index);
            }
        }
    };

    Timestamp now = 0;
    std::size_t index = 0;
    for (const std::uint8_t* record = header + 4; record + 4 <= end && index < max_frames;
         record += 4, ++index) {
        const int content = record[0] & 0x07;
        const int time_op = (record[0] >> 3) & 0x07;
        const int x0 = record[1] * frame.width / 256;
        const int y0 = record[2] * frame.height / 256;
        const std::uint8_t parameter = record[3];
        switch (content) {
            case 0:
                painter.paint([&](int, int) { return parameter; });
                break;
            case 1: {
                std::uint32_t state = 0x9E3779B9u ^ (parameter * 0x01000193u) ^ record[1];
                painter.paint([&](int, int) {
                    state ^= state << 13;
                    state ^= state >> 17;
                    state ^= state << 5;
                    return static_cast<std::uint8_t>(state >> 24);
                });
                break;
            }
            case 2:
            case 3: {
                const int radius = 1 + parameter * std::min(frame.width, frame.height) / 512;
                const std::uint8_t background = content == 2 ? 20 : 90;
                painter.paint([&](int x, int y) {
                    const int dx = x - x0;
                    const int dy = y - y0;
                    return dx * dx + dy * dy <= radius * radius ? std::uint8_t{230} : background;
                });
                break;
            }
            case 4:
                break;  // frozen: the same pixels again
            case 5:
                painter.invert();
                break;  // flicker
            case 6:
                painter.paint([&](int, int) { return std::uint8_t{255}; });
                break;
            default:
                painter.raw({record, static_cast<std::size_t>(end - record)});
                break;
        }
        now = next_time(now, time_op, parameter);
        frame.timestamp = now;
        const core::FrameResult result = tracker.process(frame);
        if (result.has_target && (!finite(result.centroid) || !finite(result.inner))) {
            fail("a target with a non-finite centroid", index);
        }
        if (result.area && !std::isfinite(*result.area)) fail("a non-finite area", index);
        if (result.has_position &&
            !(std::isfinite(result.position.x) && std::isfinite(result.position.y) &&
              std::isfinite(result.position.z))) {
            fail("a non-finite position", index);
        }
        if (!std::isfinite(result.movement)) fail("a non-finite movement", index);
        apply(pointer.update(result), index);
        if ((record[0] & 0xc0) == 0xc0) apply(pointer.release_all(), index);  // pause, reload
    }
    apply(pointer.release_all(), index);
    if (down[0] || down[1] || down[2]) fail("a button left down after release_all()", index);
    return 0;
}
