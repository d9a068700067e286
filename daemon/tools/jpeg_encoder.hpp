// SPDX-License-Identifier: MIT
#pragma once
// A BGR frame compressed as a UVC webcam's MJPEG frame: baseline JPEG, YCbCr 4:2:2 (chroma
// halved across, full height down, as UVC cameras send it; a still camera's 4:2:0 would be
// cheaper to decode than what a user's camera costs), libjpeg-turbo's standard tables scaled to
// a quality. For replaying a clip as an MJPEG camera (`run --realtime-format mjpeg`) and for the
// VM's loopback camera.

#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace raypoint::daemon {

// Compresses `bgr` (CV_8UC3) at `quality` (1-100) into `out` (replaced). Throws
// std::runtime_error with libjpeg's message when it cannot, std::invalid_argument for another
// type or an empty image.
void encode_jpeg(const cv::Mat& bgr, int quality, std::vector<std::uint8_t>& out);

}  // namespace raypoint::daemon
