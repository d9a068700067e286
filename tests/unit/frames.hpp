// SPDX-License-Identifier: MIT
#pragma once
// Small helpers shared by the unit tests: synthetic frames and FrameViews over them.

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::test {

// filter_radius = 0 puts all 16 taps on one input pixel, and a 160x120 input maps working pixel
// x to input column round((x + 0.5) * 160 / 160 - 0.5) = x: the working image is the input.
inline core::PreprocessSettings identity_settings() {
    core::PreprocessSettings settings;
    settings.filter_radius = 0.0;
    return settings;
}

inline cv::Mat uniform(cv::Size size, const cv::Vec3b& colour) {
    return cv::Mat(size, CV_8UC3, colour);
}

inline core::FrameView bgr_view(const cv::Mat& bgr, core::Timestamp timestamp = 0) {
    core::FrameView view;
    view.data = bgr.data;
    view.width = bgr.cols;
    view.height = bgr.rows;
    view.stride = static_cast<int>(bgr.step[0]);
    view.format = core::PixelFormat::bgr;
    view.timestamp = timestamp;
    return view;
}

// A YUYV image kept with its geometry; `stride` may exceed width * 2 (row padding).
struct Yuyv {
    std::vector<std::uint8_t> bytes;
    int width = 0;
    int height = 0;
    int stride = 0;

    core::FrameView view(core::Timestamp timestamp = 0) const {
        core::FrameView v;
        v.data = bytes.data();
        v.width = width;
        v.height = height;
        v.stride = stride;
        v.format = core::PixelFormat::yuyv;
        v.timestamp = timestamp;
        return v;
    }
};

// BT.601 limited range, the inverse of what the Preprocessor decodes; U and V of a pair are
// the mean of its two pixels'. Padding bytes are filled with `padding`.
inline Yuyv to_yuyv(const cv::Mat& bgr, int extra_stride = 0, std::uint8_t padding = 0) {
    Yuyv out;
    out.width = bgr.cols;
    out.height = bgr.rows;
    out.stride = bgr.cols * 2 + extra_stride;
    out.bytes.assign(static_cast<std::size_t>(out.stride) * out.height, padding);
    const auto clamp = [](int v) { return static_cast<std::uint8_t>(std::clamp(v, 0, 255)); };
    for (int y = 0; y < bgr.rows; ++y) {
        const auto* row = bgr.ptr<cv::Vec3b>(y);
        std::uint8_t* target = out.bytes.data() + static_cast<std::ptrdiff_t>(y) * out.stride;
        for (int x = 0; x + 1 < bgr.cols; x += 2) {
            int u = 0;
            int v = 0;
            for (int i = 0; i < 2; ++i) {
                const int b = row[x + i][0];
                const int g = row[x + i][1];
                const int r = row[x + i][2];
                target[x * 2 + i * 2] = clamp(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16);
                u += ((-38 * r - 74 * g + 112 * b + 128) >> 8) + 128;
                v += ((112 * r - 94 * g - 18 * b + 128) >> 8) + 128;
            }
            target[x * 2 + 1] = clamp(u / 2);
            target[x * 2 + 3] = clamp(v / 2);
        }
    }
    return out;
}

// White 640x480 (or `size`) with a black disk: the tracker's standard synthetic target.
inline void draw_disk_frame(cv::Mat& frame, cv::Point centre, int radius,
                            cv::Size size = cv::Size(640, 480)) {
    frame.create(size, CV_8UC3);
    frame.setTo(cv::Scalar::all(255));
    cv::circle(frame, centre, radius, cv::Scalar::all(0), cv::FILLED, cv::LINE_8);
}

// Eight fixed noise patterns of +-4 a channel, cycled: cheap and deterministic.
inline const std::array<cv::Mat, 8>& noise() {
    static const std::array<cv::Mat, 8> patterns = [] {
        std::array<cv::Mat, 8> p;
        cv::RNG rng(7);
        for (auto& m : p) {
            m.create(480, 640, CV_8UC3);
            rng.fill(m, cv::RNG::UNIFORM, 0, 9);
        }
        return p;
    }();
    return patterns;
}

// Disk `radius` at `centre` (input pixels): black (0..8) on white (243..251): 4 and 247 plus
// 0..8 - 4 of noise (no saturation).
inline cv::Mat noisy_disk(int frame, cv::Point centre, int radius) {
    cv::Mat image(480, 640, CV_8UC3, cv::Scalar::all(247));
    cv::circle(image, centre, radius, cv::Scalar::all(4), cv::FILLED);
    image += noise()[static_cast<std::size_t>(frame) % 8];
    image -= cv::Scalar::all(4);
    return image;
}

}  // namespace raypoint::test
