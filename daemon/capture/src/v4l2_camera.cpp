// SPDX-License-Identifier: MIT
#include "raypoint/capture/v4l2_camera.hpp"

#include <fcntl.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <optional>
#include <utility>

#include "raypoint/capture/camera_errors.hpp"
#include "raypoint/capture/v4l2_device.hpp"

namespace raypoint::daemon {

namespace fs = std::filesystem;

namespace {

constexpr int buffer_count = 4;  // enough to absorb a slow frame without the driver dropping

core::Timestamp monotonic_us() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return core::seconds_to_us(std::int64_t{now.tv_sec}) + now.tv_nsec / 1000;
}

}  // namespace

V4l2Camera::V4l2Camera(CameraOptions options) : options_(std::move(options)) {
    try {
        open_device();
    } catch (...) {
        release();
        throw;
    }
}

V4l2Camera::~V4l2Camera() {
    release();
}

void V4l2Camera::open_device() {
    if (options_.settings.device != "auto") {
        std::error_code error;
        // A by-id/by-path link names the same camera after a replug; resolve it every time.
        const fs::path node = fs::canonical(options_.settings.device, error);
        if (error) {
            throw CameraError(camera_error_message(options_.settings.device, "open", error.value(),
                                                   list_capture_devices()));
        }
        const std::string& device = options_.settings.device;
        const std::string label =
            node.string() == device ? device : device + " (" + node.string() + ")";
        open_node(node.string(), label);
        return;
    }
    std::string reasons;
    for (const std::string& node : video_nodes()) {
        try {
            open_node(node, node);
            // "Actually streams": some capture nodes (an idle loopback, a broken camera) accept
            // every ioctl and then never deliver.
            const Capture first = next(options_.first_frame_timeout_ms);
            if (first.status == CaptureStatus::frame) return;
            reasons += "; " + node + ": no frame within " +
                       std::to_string(options_.first_frame_timeout_ms) + " ms";
        } catch (const CameraError& error) {
            reasons += std::string("; ") + error.what();
        }
        release();
    }
    if (reasons.empty()) reasons = "; there is no video capture device (is a camera plugged in?)";
    throw CameraError("auto: no camera could stream" + reasons);
}

void V4l2Camera::fail(const std::string& call, int error_number) const {
    throw CameraError(camera_error_message(
        label_, call, error_number,
        error_number == ENOENT ? list_capture_devices() : std::vector<std::string>{}));
}

void V4l2Camera::open_node(const std::string& node, const std::string& label) {
    node_ = node;
    label_ = label;
    fd_ = open(node.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) fail("open", errno);
    v4l2_capability cap{};
    if (xioctl(fd_, VIDIOC_QUERYCAP, &cap) < 0) {
        if (errno == ENOTTY) throw CameraError(label_ + ": not a V4L2 video device");
        fail("VIDIOC_QUERYCAP", errno);
    }
    card_ = card_of(cap);
    if (!is_streaming_capture(cap)) {
        throw CameraError(label_ + " (" + card_ +
                          "): not a video capture device with streaming I/O (a camera's "
                          "metadata node? the capture devices are listed by `v4l2-ctl "
                          "--list-devices`)");
    }
    negotiate_format();
    if (options_.settings.lock_exposure) lock_controls();
    start_streaming();
}

void V4l2Camera::negotiate_format() {
    const std::vector<CameraMode> offered = offered_modes(fd_);
    const cv::Size least = options_.capture_least();
    // A camera without a mode that large still works at any size the core can read.
    auto chosen = choose_format(offered, least);
    if (!chosen) chosen = choose_format(offered, options_.working);
    if (!chosen) {
        std::string list;
        for (const auto& mode : offered)
            list += (list.empty() ? "" : ", ") + describe(mode);
        throw CameraError(label_ + ": no YUYV or MJPEG mode of at least " +
                          std::to_string(options_.working.width) + "x" +
                          std::to_string(options_.working.height) +
                          " (offered: " + (list.empty() ? "nothing" : list) + ")");
    }
    v4l2_format format{};
    format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    format.fmt.pix.width = static_cast<__u32>(chosen->size.width);
    format.fmt.pix.height = static_cast<__u32>(chosen->size.height);
    format.fmt.pix.pixelformat = chosen->fourcc;
    format.fmt.pix.field = V4L2_FIELD_NONE;  // progressive: the core has no deinterlacer
    if (xioctl(fd_, VIDIOC_S_FMT, &format) < 0) fail("VIDIOC_S_FMT " + describe(*chosen), errno);
    // S_FMT adjusts rather than fails: check what the driver actually set.
    const v4l2_pix_format& got = format.fmt.pix;
    mode_ = {got.pixelformat, {static_cast<int>(got.width), static_cast<int>(got.height)}, {}};
    if (got.pixelformat != chosen->fourcc || mode_.size.width < options_.working.width ||
        mode_.size.height < options_.working.height ||
        (got.pixelformat == V4L2_PIX_FMT_YUYV && mode_.size.width % 2 != 0)) {
        throw CameraError(label_ + ": asked for " + describe(*chosen) + ", the driver set " +
                          describe(mode_));
    }
    if (chosen->fourcc != V4L2_PIX_FMT_YUYV && !jpeg_) {
        // The mode's own size as the least size: a full-size decode unless asked to scale.
        jpeg_ = std::make_unique<JpegDecoder>(options_.scaled_mjpeg ? least : mode_.size);
    }
    const int packed = chosen->fourcc == V4L2_PIX_FMT_YUYV ? mode_.size.width * 2 : 0;
    stride_ = std::max(static_cast<int>(got.bytesperline), packed);
}

void V4l2Camera::lock_controls() {
    lock_report_.clear();
    // Under auto exposure the exposure controls read back what the camera settled on; switching
    // to manual may jump to the last manually set value, so the settled one is written back.
    std::vector<std::pair<std::uint32_t, std::int32_t>> exposure;
    for (const std::uint32_t id : {V4L2_CID_EXPOSURE_ABSOLUTE, V4L2_CID_EXPOSURE}) {
        if (const auto value = control_value(fd_, id)) exposure.emplace_back(id, *value);
    }
    struct Lock {
        std::uint32_t id;
        std::int32_t value;
        const char* name;
        const char* what;
    };
    for (const Lock& lock :
         {Lock{V4L2_CID_EXPOSURE_AUTO, V4L2_EXPOSURE_MANUAL, "auto exposure", "manual"},
          Lock{V4L2_CID_AUTOGAIN, 0, "autogain", "off"},
          Lock{V4L2_CID_AUTO_WHITE_BALANCE, 0, "auto white balance", "off"}}) {
        const auto before = control_value(fd_, lock.id);
        std::string entry = std::string(lock.name) + ": ";
        if (!before) {
            lock_report_.push_back(entry + "absent");
            continue;
        }
        if (!set_control(fd_, lock.id, lock.value)) {
            lock_report_.push_back(entry + "failed (" + std::strerror(errno) + ")");
            continue;
        }
        saved_controls_.push_back({lock.id, *before});
        entry += lock.what;
        if (lock.id == V4L2_CID_EXPOSURE_AUTO) {
            for (const auto& [id, value] : exposure) {
                if (!set_control(fd_, id, value)) continue;
                saved_controls_.push_back({id, value});
                entry += " (exposure kept at " + std::to_string(value) + ")";
            }
        }
        lock_report_.push_back(entry);
    }
}

void V4l2Camera::start_streaming() {
    v4l2_requestbuffers request{};
    request.count = buffer_count;
    request.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    request.memory = V4L2_MEMORY_MMAP;
    if (xioctl(fd_, VIDIOC_REQBUFS, &request) < 0) fail("VIDIOC_REQBUFS", errno);
    // The driver may grant fewer; with one, the buffer we lend out would stall the stream.
    if (request.count < 2) {
        throw CameraError(label_ + ": VIDIOC_REQBUFS granted " + std::to_string(request.count) +
                          " buffer(s), 2 are needed");
    }
    for (std::uint32_t i = 0; i < request.count; ++i) {
        v4l2_buffer buffer{};
        buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buffer.memory = V4L2_MEMORY_MMAP;
        buffer.index = i;
        if (xioctl(fd_, VIDIOC_QUERYBUF, &buffer) < 0) fail("VIDIOC_QUERYBUF", errno);
        void* start = mmap(nullptr, buffer.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd_,
                           static_cast<off_t>(buffer.m.offset));
        if (start == MAP_FAILED) fail("mmap", errno);
        buffers_.push_back({start, buffer.length});
        if (!queue(i)) fail("VIDIOC_QBUF", errno);
    }
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(fd_, VIDIOC_STREAMON, &type) < 0) fail("VIDIOC_STREAMON", errno);
    streaming_ = true;
    last_timestamp_ = -1;
}

bool V4l2Camera::queue(std::uint32_t index) noexcept {
    v4l2_buffer buffer{};
    buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buffer.memory = V4L2_MEMORY_MMAP;
    buffer.index = index;
    return xioctl(fd_, VIDIOC_QBUF, &buffer) == 0;
}

Capture V4l2Camera::lost(const std::string& call, int error_number) {
    Capture capture;
    capture.status = CaptureStatus::lost;
    capture.reason = camera_error_message(label_, call, error_number);
    return capture;
}

Capture V4l2Camera::next(int timeout_ms) {
    if (!streaming_) {
        return Capture{CaptureStatus::lost, {}, label_ + ": not streaming (released); reopen()"};
    }
    if (held_ >= 0) {
        const auto index = static_cast<std::uint32_t>(std::exchange(held_, -1));
        if (!queue(index)) return lost("VIDIOC_QBUF", errno);
    }
    const core::Timestamp deadline = monotonic_us() + core::Timestamp{timeout_ms} * 1000;
    for (;;) {
        const auto left_ms = static_cast<int>(
            std::max<core::Timestamp>(0, (deadline - monotonic_us() + 999) / 1000));
        pollfd ready{fd_, POLLIN, 0};
        const int count = poll(&ready, 1, left_ms);
        if (count < 0 && errno == EINTR) continue;
        if (count < 0) return lost("poll", errno);
        if (count == 0) return Capture{};  // timeout
        // With buffers queued and streaming on, POLLERR means the device failed (unplugged).
        if (ready.revents & (POLLERR | POLLHUP | POLLNVAL)) return lost("poll (POLLERR)", ENODEV);
        v4l2_buffer buffer{};
        buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buffer.memory = V4L2_MEMORY_MMAP;
        if (xioctl(fd_, VIDIOC_DQBUF, &buffer) < 0) {
            if (errno == EAGAIN) continue;  // woken, but another reader took it: wait again
            return lost("VIDIOC_DQBUF", errno);
        }
        if (buffer.index >= buffers_.size()) return lost("VIDIOC_DQBUF (bad index)", EIO);
        Capture capture;
        // The driver's capture time is closest to the light: prefer it when it is monotonic.
        const bool monotonic =
            (buffer.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
        capture.frame.timestamp = monotonic
                                      ? core::seconds_to_us(std::int64_t{buffer.timestamp.tv_sec}) +
                                            buffer.timestamp.tv_usec
                                      : monotonic_us();
        // V4L2_BUF_FLAG_ERROR: the driver says the data is corrupt (a USB packet was lost).
        const bool corrupt = (buffer.flags & V4L2_BUF_FLAG_ERROR) != 0;
        if (corrupt || !make_frame(buffer.index, buffer.bytesused, capture)) {
            if (!queue(buffer.index)) return lost("VIDIOC_QBUF", errno);
            continue;
        }
        // The core's timing needs time to move forward even if a driver repeats a timestamp.
        if (capture.frame.timestamp <= last_timestamp_) {
            capture.frame.timestamp = last_timestamp_ + 1;
        }
        last_timestamp_ = capture.frame.timestamp;
        // Frame ready, for the latency to the output: when the driver stamped the buffer (for
        // UVC that is the start of the frame's transfer, so the latency includes its USB time).
        capture.ready = capture.frame.timestamp;
        capture.status = CaptureStatus::frame;
        return capture;
    }
}

bool V4l2Camera::make_frame(std::uint32_t index, std::size_t bytesused, Capture& capture) {
    const Buffer& buffer = buffers_[index];
    const auto* data = static_cast<const std::uint8_t*>(buffer.start);
    if (bytesused == 0 || bytesused > buffer.length) bytesused = buffer.length;
    core::FrameView& frame = capture.frame;
    if (mode_.fourcc == V4L2_PIX_FMT_YUYV) {
        // Short frames happen when the camera drops USB packets; the core reads every row.
        const std::size_t needed =
            std::size_t(stride_) * std::size_t(mode_.size.height - 1) + mode_.size.width * 2U;
        if (bytesused < needed) return false;
        frame.data = data;
        frame.width = mode_.size.width;
        frame.height = mode_.size.height;
        frame.stride = stride_;
        frame.format = core::PixelFormat::yuyv;
        held_ = static_cast<int>(index);  // the driver gets it back on the next call
        return true;
    }
    // MJPEG, the slow path: a CPU decode of every frame (a few ms at 640x480; less with
    // scaled_mjpeg). Some UVC cameras omit the Huffman tables; libjpeg-turbo supplies the
    // standard ones.
    if (!jpeg_->decode(data, bytesused)) return false;  // a corrupt JPEG: skip it
    const cv::Mat& bgr = jpeg_->bgr();
    held_ = static_cast<int>(index);  // queued on the next call, like a YUYV buffer
    frame.data = bgr.data;
    frame.width = bgr.cols;
    frame.height = bgr.rows;
    frame.stride = static_cast<int>(bgr.step[0]);
    frame.format = core::PixelFormat::bgr;
    return true;
}

void V4l2Camera::release() noexcept {
    if (fd_ >= 0) {
        if (streaming_) {
            v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
            xioctl(fd_, VIDIOC_STREAMOFF, &type);  // errors ignored: the device may be gone
        }
        // Put the automatic controls back in reverse order (auto exposure after exposure).
        for (auto it = saved_controls_.rbegin(); it != saved_controls_.rend(); ++it) {
            set_control(fd_, it->id, it->value);
        }
    }
    for (const Buffer& buffer : buffers_)
        munmap(buffer.start, buffer.length);
    buffers_.clear();
    if (fd_ >= 0) {
        // Freeing the buffers (REQBUFS 0) happens on close; the mappings are gone already.
        close(fd_);
        fd_ = -1;
    }
    saved_controls_.clear();
    streaming_ = false;
    held_ = -1;
}

bool V4l2Camera::reopen() {
    release();
    try {
        open_device();
        last_error_.clear();
        return true;
    } catch (const std::exception& error) {
        last_error_ = error.what();
        release();
        return false;
    }
}

std::string V4l2Camera::description() const {
    std::string text = label_ + ": " + card_ + "; " + describe(mode_);
    if (mode_.fourcc != V4L2_PIX_FMT_YUYV) {
        const int eighths = options_.scaled_mjpeg
                                ? JpegDecoder::scale_for(mode_.size, options_.capture_least())
                                : 8;
        text += eighths == 8 ? std::string(" (decoded on the CPU: the slow path)")
                             : " (decoded on the CPU at " + std::to_string(eighths) +
                                   "/8 scale: the slow path)";
    }
    text += ", " + std::to_string(buffers_.size()) + " buffers";
    if (fd_ < 0) text += ", closed";
    for (const std::string& entry : lock_report_)
        text += "; " + entry;
    return text;
}

}  // namespace raypoint::daemon
