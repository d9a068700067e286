// SPDX-License-Identifier: MIT
#pragma once
// A V4L2 webcam as a FrameSource: opens the device, negotiates the mode (camera_format.hpp),
// streams through memory-mapped driver buffers and hands out frames without copying (YUYV) or
// decoded once by libjpeg-turbo (MJPEG, the slow path).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "raypoint/capture/camera_format.hpp"
#include "raypoint/capture/frame_source.hpp"
#include "raypoint/capture/jpeg_decoder.hpp"
#include "raypoint/config/config.hpp"

namespace raypoint::daemon {

struct CameraOptions {
    // The user's [camera] settings (config.hpp):
    // - device: "/dev/video0", a stable link such as "/dev/v4l/by-id/usb-...-video-index0"
    //   (resolved on every open, so it follows the camera to a new /dev/videoN after a replug),
    //   or "auto": the first /dev/videoN (in numeric order) that is a streaming capture device
    //   and delivers a frame within first_frame_timeout_ms;
    // - min_width x min_height: the camera's smallest mode at least this (and `working`) large is
    //   asked for;
    // - lock_exposure: auto exposure, gain and white balance off where the camera has them; the
    //   values before are put back on release(), since cameras keep controls after the program
    //   exits.
    config::CameraSettings settings;
    cv::Size working{160, 120};  // the core's working size: frames must be at least this big
    int first_frame_timeout_ms = 2000;
    // MJPEG modes: decode at the smallest n/8 scale still at least capture_least()
    // (jpeg_decoder.hpp) instead of at full size. realworld through a q80 JPEG at 640x480:
    // full decode 100% tracked, depth r 0.906; 1/2 scale 100%, 0.913; 1/4 (160x120) 100%, 0.758.
    bool scaled_mjpeg = true;

    // Per axis the larger of `working` and the configured minimum.
    cv::Size capture_least() const noexcept {
        return {std::max(working.width, settings.min_width),
                std::max(working.height, settings.min_height)};
    }
};

class V4l2Camera final : public FrameSource {
  public:
    // Opens and starts streaming. Throws CameraError (camera_errors.hpp) with the device, the
    // failing call and what to do.
    explicit V4l2Camera(CameraOptions options);
    // Starts released, as if lost: next() reports lost until reopen() succeeds. For a service
    // started before its camera is plugged in.
    struct StartClosed {};
    V4l2Camera(CameraOptions options, StartClosed) : options_(std::move(options)) {}
    ~V4l2Camera() override;
    V4l2Camera(const V4l2Camera&) = delete;
    V4l2Camera& operator=(const V4l2Camera&) = delete;

    Capture next(int timeout_ms) override;
    int wait_fd() const noexcept override { return fd_; }
    void release() noexcept override;
    bool reopen() override;
    const std::string& last_error() const noexcept override { return last_error_; }
    std::string description() const override;

    const std::string& node() const noexcept { return node_; }  // the /dev/videoN in use
    const CameraMode& mode() const noexcept { return mode_; }   // the negotiated mode
    // One entry a control when lock_exposure: "auto exposure: manual (exposure kept at 156)",
    // "autogain: off", "auto white balance: absent", "...: failed (<strerror>)".
    const std::vector<std::string>& exposure_lock() const noexcept { return lock_report_; }

  private:
    struct Buffer {
        void* start = nullptr;
        std::size_t length = 0;
    };
    struct SavedControl {
        std::uint32_t id = 0;
        std::int32_t value = 0;
    };

    void open_device();  // by options_.device; throws CameraError
    void open_node(const std::string& node, const std::string& label);  // throws CameraError
    void negotiate_format();
    void lock_controls();
    void start_streaming();
    [[noreturn]] void fail(const std::string& call, int error_number) const;
    bool queue(std::uint32_t index) noexcept;
    Capture lost(const std::string& call, int error_number);
    // The frame in buffer `index` (bytesused long), or false for a corrupt one to skip.
    bool make_frame(std::uint32_t index, std::size_t bytesused, Capture& capture);

    CameraOptions options_;
    std::string label_;  // how messages name the device: the option, plus the node if different
    std::string node_;
    std::string card_;  // VIDIOC_QUERYCAP: the camera's name, driver and bus
    int fd_ = -1;
    CameraMode mode_;
    int stride_ = 0;  // bytes a row, from VIDIOC_S_FMT (drivers may pad rows)
    std::vector<Buffer> buffers_;
    int held_ = -1;  // the buffer lent out with the last frame, queued again on the next call
    bool streaming_ = false;
    std::unique_ptr<JpegDecoder> jpeg_;  // MJPEG modes: decodes into its frame, reused
    core::Timestamp last_timestamp_ = -1;
    std::vector<SavedControl> saved_controls_;
    std::vector<std::string> lock_report_;
    std::string last_error_;
};

}  // namespace raypoint::daemon
