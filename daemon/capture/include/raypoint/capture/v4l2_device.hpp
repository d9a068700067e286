// SPDX-License-Identifier: MIT
#pragma once
// The V4L2 ioctls a camera needs before streaming, as plain functions on a file descriptor:
// finding capture nodes, what a node offers, and reading and writing controls.

#include <linux/videodev2.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "raypoint/capture/camera_format.hpp"

namespace raypoint::daemon {

// ioctl, restarted when a signal interrupts it.
int xioctl(int fd, unsigned long request, void* arg);

// /dev/videoN in numeric order (video2 before video10), as `auto` tries them.
std::vector<std::string> video_nodes();

// A video capture node with streaming I/O, judged by device_caps (this node) when the driver
// sets it rather than `capabilities` (the whole device): a UVC camera's metadata node shares
// VIDEO_CAPTURE in the latter but not the former.
bool is_streaming_capture(const v4l2_capability& cap);

// "Integrated Camera, uvcvideo, usb-0000:00:14.0-8": VIDIOC_QUERYCAP's card, driver and bus.
std::string card_of(const v4l2_capability& cap);

// Every /dev/videoN that is a streaming capture node, as "/dev/video0 (<card_of>)", plus the
// nodes we may not open, with the reason. For error messages and status output.
std::vector<std::string> list_capture_devices();

// Every pixel format and frame size the node offers for single-planar capture
// (VIDIOC_ENUM_FMT, then VIDIOC_ENUM_FRAMESIZES discrete or stepwise per format).
std::vector<CameraMode> offered_modes(int fd);

// The control's current value if the node has it and it is not disabled (VIDIOC_QUERYCTRL,
// VIDIOC_G_CTRL), else nothing.
std::optional<std::int32_t> control_value(int fd, std::uint32_t id);

// VIDIOC_S_CTRL; false with errno set when the driver refuses.
bool set_control(int fd, std::uint32_t id, std::int32_t value);

}  // namespace raypoint::daemon
