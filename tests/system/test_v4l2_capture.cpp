// SPDX-License-Identifier: MIT
// A real capture: opens $RAYPOINT_TEST_CAMERA (else "auto"), takes 10 frames and checks their
// size, format, stride and timestamps, then release() and reopen() and 3 frames more, then the
// exposure lock. Exit 77 (CTest: skipped) when the machine has no capture device; the VM job
// runs it against vivid or v4l2loopback.

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "raypoint/capture/camera_errors.hpp"
#include "raypoint/capture/v4l2_camera.hpp"
#include "raypoint/capture/v4l2_device.hpp"

namespace {

using raypoint::daemon::CameraOptions;
using raypoint::daemon::CaptureStatus;
using raypoint::daemon::V4l2Camera;

constexpr int skipped = 77;
constexpr int timeout_ms = 2000;  // generous: a UVC camera may take a second to start

int failures = 0;

void check(bool ok, const std::string& what) {
    if (ok) return;
    std::printf("FAIL: %s\n", what.c_str());
    ++failures;
}

// `count` frames: each the negotiated size at least, a known format, a plausible stride, and
// a timestamp after the previous one.
void capture(V4l2Camera& camera, int count, const CameraOptions& options) {
    raypoint::core::Timestamp last = -1;
    for (int i = 0; i < count; ++i) {
        const auto got = camera.next(timeout_ms);
        if (got.status != CaptureStatus::frame) {
            check(false, "frame " + std::to_string(i) + ": " +
                             (got.status == CaptureStatus::timeout ? "timeout" : got.reason));
            return;
        }
        const auto& f = got.frame;
        const bool yuyv = f.format == raypoint::core::PixelFormat::yuyv;
        std::printf("frame %d: %dx%d %s stride %d t %lld us%s\n", i, f.width, f.height,
                    yuyv ? "yuyv" : "bgr", f.stride, static_cast<long long>(f.timestamp),
                    last < 0 ? "" : (" (+" + std::to_string(f.timestamp - last) + ")").c_str());
        check(f.data != nullptr, "data");
        check(f.width >= options.working.width && f.height >= options.working.height,
              "frame smaller than the working size");
        check(f.stride >= f.width * (yuyv ? 2 : 3), "stride shorter than a row");
        check(!yuyv || f.width % 2 == 0, "odd YUYV width");
        check(f.timestamp > last, "timestamp did not increase");
        last = f.timestamp;
    }
}

}  // namespace

int main() {
    const char* env = std::getenv("RAYPOINT_TEST_CAMERA");
    CameraOptions options;
    options.settings.device = env && *env ? env : "auto";
    const auto devices = raypoint::daemon::list_capture_devices();
    if (options.settings.device == "auto" && devices.empty()) {
        std::printf(
            "SKIP: no video capture device (/dev/video*) on this machine; load vivid "
            "(modprobe vivid) or set RAYPOINT_TEST_CAMERA\n");
        return skipped;
    }
    for (const auto& device : devices)
        std::printf("capture device: %s\n", device.c_str());
    try {
        V4l2Camera camera(options);
        std::printf("opened: %s\n", camera.description().c_str());
        capture(camera, 10, options);

        camera.release();
        check(camera.next(10).status == CaptureStatus::lost, "next() after release() not lost");
        check(camera.reopen(), "reopen: " + camera.last_error());
        std::printf("reopened: %s\n", camera.description().c_str());
        capture(camera, 3, options);
        camera.release();

        options.settings.lock_exposure = true;
        V4l2Camera locked(options);
        std::printf("with lock_exposure: %s\n", locked.description().c_str());
        check(locked.exposure_lock().size() == 3, "one lock report a control");
        capture(locked, 3, options);
    } catch (const std::exception& error) {
        std::printf("FAIL: %s\n", error.what());
        return 1;
    }
    std::printf("%s\n", failures == 0 ? "PASS" : "FAILED");
    return failures == 0 ? 0 : 1;
}
