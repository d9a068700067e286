// SPDX-License-Identifier: MIT
#include "raypoint/capture/camera_format.hpp"

#include <linux/videodev2.h>

namespace raypoint::daemon {

namespace {

enum class Encoding { yuyv, mjpeg, other };

Encoding encoding_of(std::uint32_t fourcc) {
    if (fourcc == V4L2_PIX_FMT_YUYV) return Encoding::yuyv;
    // Old drivers (gspca, some UVC quirks) say JPEG for the same motion-JPEG stream.
    if (fourcc == V4L2_PIX_FMT_MJPEG || fourcc == V4L2_PIX_FMT_JPEG) return Encoding::mjpeg;
    return Encoding::other;
}

// The smallest min + k * step that is >= target and <= max (and even when `even`), or nothing.
std::optional<int> smallest_on_grid(int min, int max, int step, int target, bool even) {
    if (min <= 0 || max < min) return std::nullopt;
    if (step <= 0) step = 1;  // a broken driver; treat as continuous rather than loop forever
    int value = min;
    if (target > min) value = min + (target - min + step - 1) / step * step;
    // An odd step alternates parity, so at most one more step makes the value even.
    if (even && value % 2 != 0) value += step;
    if (even && value % 2 != 0) return std::nullopt;
    if (value > max) return std::nullopt;
    return value;
}

// The mode's smallest usable concrete size, or nothing when none is >= working.
std::optional<cv::Size> smallest_fit(const CameraMode& mode, cv::Size working, bool even_width) {
    if (mode.range) {
        const SizeRange& r = *mode.range;
        const auto w =
            smallest_on_grid(r.min.width, r.max.width, r.step.width, working.width, even_width);
        const auto h =
            smallest_on_grid(r.min.height, r.max.height, r.step.height, working.height, false);
        if (!w || !h) return std::nullopt;
        return cv::Size(*w, *h);
    }
    const cv::Size s = mode.size;
    if (s.width < working.width || s.height < working.height) return std::nullopt;
    if (even_width && s.width % 2 != 0) return std::nullopt;
    return s;
}

bool smaller(cv::Size a, cv::Size b) {
    // 64-bit areas: a stepwise maximum can be large, and two ints multiplied may overflow.
    const auto area_a = static_cast<long long>(a.width) * a.height;
    const auto area_b = static_cast<long long>(b.width) * b.height;
    return area_a != area_b ? area_a < area_b : a.width < b.width;
}

std::optional<CameraMode> best_of(const std::vector<CameraMode>& offered, Encoding wanted,
                                  cv::Size working) {
    std::optional<CameraMode> best;
    for (const CameraMode& mode : offered) {
        if (encoding_of(mode.fourcc) != wanted) continue;
        const auto size = smallest_fit(mode, working, wanted == Encoding::yuyv);
        if (!size) continue;
        if (!best || smaller(*size, best->size)) best = CameraMode{mode.fourcc, *size, {}};
    }
    return best;
}

}  // namespace

std::optional<CameraMode> choose_format(const std::vector<CameraMode>& offered, cv::Size working) {
    if (auto yuyv = best_of(offered, Encoding::yuyv, working)) return yuyv;
    return best_of(offered, Encoding::mjpeg, working);
}

std::string fourcc_name(std::uint32_t fourcc) {
    std::string name;
    for (int shift = 0; shift < 32; shift += 8) {
        const auto c = static_cast<char>((fourcc >> shift) & 0xffU);
        name += (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    // Fourccs are padded with spaces ("GREY", but "Y16 "): trailing blanks only confuse logs.
    while (!name.empty() && name.back() == ' ')
        name.pop_back();
    return name;
}

std::string describe(const CameraMode& mode) {
    const auto size = [](cv::Size s) {
        return std::to_string(s.width) + "x" + std::to_string(s.height);
    };
    std::string text = fourcc_name(mode.fourcc) + " ";
    if (!mode.range) return text + size(mode.size);
    return text + size(mode.range->min) + ".." + size(mode.range->max) + " step " +
           size(mode.range->step);
}

}  // namespace raypoint::daemon
