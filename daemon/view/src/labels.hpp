// SPDX-License-Identifier: MIT
#pragma once
// The text of the pictures: numbers formatted printf-style, labels in OpenCV's plain font.

#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

namespace raypoint::view::detail {

inline std::string format_number(const char* pattern, double value) {
    char text[48];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// Anti-aliased, one pixel thick: for reading, never for a test to find by colour.
inline void put_label(cv::Mat& image, const std::string& text, cv::Point at,
                      const cv::Scalar& color, double scale) {
    cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, color, 1, cv::LINE_AA);
}

}  // namespace raypoint::view::detail
