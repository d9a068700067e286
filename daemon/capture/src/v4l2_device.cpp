// SPDX-License-Identifier: MIT
#include "raypoint/capture/v4l2_device.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

namespace raypoint::daemon {

namespace fs = std::filesystem;

int xioctl(int fd, unsigned long request, void* arg) {
    int result = 0;
    do {
        result = ioctl(fd, request, arg);
    } while (result < 0 && errno == EINTR);
    return result;
}

std::vector<std::string> video_nodes() {
    std::vector<std::pair<int, std::string>> nodes;
    std::error_code error;
    for (fs::directory_iterator it("/dev", error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= 5 || name.compare(0, 5, "video") != 0) continue;
        const auto digit = [](char c) { return c >= '0' && c <= '9'; };
        if (!std::all_of(name.begin() + 5, name.end(), digit) || name.size() > 14) continue;
        nodes.emplace_back(std::stoi(name.substr(5)), it->path().string());
    }
    std::sort(nodes.begin(), nodes.end());
    std::vector<std::string> paths;
    paths.reserve(nodes.size());
    for (auto& node : nodes)
        paths.push_back(std::move(node.second));
    return paths;
}

bool is_streaming_capture(const v4l2_capability& cap) {
    const std::uint32_t caps =
        (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    return (caps & V4L2_CAP_VIDEO_CAPTURE) && (caps & V4L2_CAP_STREAMING);
}

std::string card_of(const v4l2_capability& cap) {
    // The fields are fixed-size byte arrays, NUL-terminated only when shorter than the array.
    const auto text = [](const __u8* bytes, std::size_t size) {
        const auto* chars = reinterpret_cast<const char*>(bytes);
        return std::string(chars, strnlen(chars, size));
    };
    return text(cap.card, sizeof cap.card) + ", " + text(cap.driver, sizeof cap.driver) + ", " +
           text(cap.bus_info, sizeof cap.bus_info);
}

std::vector<std::string> list_capture_devices() {
    std::vector<std::string> devices;
    for (const std::string& node : video_nodes()) {
        // QUERYCAP needs no exclusive access: opening read-only disturbs no one streaming.
        const int fd = open(node.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            devices.push_back(node + " (cannot open: " + std::strerror(errno) + ")");
            continue;
        }
        v4l2_capability cap{};
        if (xioctl(fd, VIDIOC_QUERYCAP, &cap) == 0 && is_streaming_capture(cap)) {
            devices.push_back(node + " (" + card_of(cap) + ")");
        }
        close(fd);
    }
    return devices;
}

namespace {

cv::Size size_of(std::uint32_t width, std::uint32_t height) {
    return {static_cast<int>(width), static_cast<int>(height)};
}

}  // namespace

std::vector<CameraMode> offered_modes(int fd) {
    std::vector<CameraMode> modes;
    v4l2_fmtdesc format{};
    format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    for (format.index = 0; xioctl(fd, VIDIOC_ENUM_FMT, &format) == 0; ++format.index) {
        v4l2_frmsizeenum size{};
        size.pixel_format = format.pixelformat;
        bool enumerated = false;
        for (size.index = 0; xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &size) == 0; ++size.index) {
            enumerated = true;
            if (size.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                const auto& d = size.discrete;
                modes.push_back({format.pixelformat, size_of(d.width, d.height), {}});
                continue;
            }
            // STEPWISE and CONTINUOUS are one entry at index 0; CONTINUOUS has a step of 1.
            const auto& s = size.stepwise;
            modes.push_back(
                {format.pixelformat,
                 {},
                 SizeRange{size_of(s.min_width, s.min_height), size_of(s.max_width, s.max_height),
                           size_of(s.step_width, s.step_height)}});
            break;
        }
        // A driver without VIDIOC_ENUM_FRAMESIZES: offer any size; VIDIOC_S_FMT will adjust it.
        if (!enumerated) {
            modes.push_back(
                {format.pixelformat, {}, SizeRange{{1, 1}, {1 << 14, 1 << 14}, {1, 1}}});
        }
    }
    return modes;
}

std::optional<std::int32_t> control_value(int fd, std::uint32_t id) {
    v4l2_queryctrl query{};
    query.id = id;
    if (xioctl(fd, VIDIOC_QUERYCTRL, &query) < 0) return std::nullopt;  // EINVAL: not there
    if (query.flags & V4L2_CTRL_FLAG_DISABLED) return std::nullopt;
    v4l2_control control{id, 0};
    if (xioctl(fd, VIDIOC_G_CTRL, &control) < 0) return std::nullopt;
    return control.value;
}

bool set_control(int fd, std::uint32_t id, std::int32_t value) {
    v4l2_control control{id, value};
    return xioctl(fd, VIDIOC_S_CTRL, &control) == 0;
}

}  // namespace raypoint::daemon
