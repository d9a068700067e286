// SPDX-License-Identifier: MIT
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "measure.hpp"
#include "raypoint/scene/truth.hpp"

namespace raypoint::scene {

Truth measure_mask(const cv::Mat& mask, cv::Point offset, cv::Size frame) {
    CV_Assert(mask.type() == CV_8U);
    Truth truth;
    if (mask.empty()) return truth;
    const cv::Moments m = cv::moments(mask, true);
    if (m.m00 <= 0) return truth;
    const cv::Rect box = cv::boundingRect(mask);
    const double w = frame.width;
    const double h = frame.height;
    truth.present = true;
    truth.cx = (m.m10 / m.m00 + offset.x + 0.5) / w;
    truth.cy = (m.m01 / m.m00 + offset.y + 0.5) / h;
    truth.area = m.m00 / (w * h);
    truth.bx = (box.x + offset.x) / w;
    truth.by = (box.y + offset.y) / h;
    truth.bw = box.width / w;
    truth.bh = box.height / h;
    return truth;
}

Truth truth_from_mask(const cv::Mat& mask) {
    return measure_mask(mask, {0, 0}, mask.size());
}

bool has_moved(const Truth& previous, const Truth& current) {
    if (!previous.present || !current.present) return false;
    const double dx = (current.cx - previous.cx) * 160;
    const double dy = (current.cy - previous.cy) * 120;
    return std::hypot(dx, dy) > moving_centroid_px ||
           std::abs(current.area - previous.area) > moving_area_change * previous.area;
}

}  // namespace raypoint::scene
