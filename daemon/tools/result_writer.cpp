// SPDX-License-Identifier: MIT
#include "result_writer.hpp"

#include <cmath>
#include <initializer_list>
#include <string>

namespace raypoint::daemon {
namespace {

// Fractions of the frame: 5 decimals are 1/100 of a pixel at 1920 wide.
std::string number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.5f", value);
    return buffer;
}

}  // namespace

ResultWriter::ResultWriter(std::FILE* out, OutputFormat format) : out_(out), format_(format) {
    if (format_ == OutputFormat::csv) {
        std::fputs("frame,t,state,cx,cy,area,ix,iy,px,py,pz,movement,us\n", out_);
    }
}

void ResultWriter::write(const core::FrameResult& r, long microseconds) {
    const std::string state(core::to_string(r.state));
    const double seconds = static_cast<double>(r.timestamp) * 1e-6;
    const long movement = std::lround(r.movement);
    std::string line;
    switch (format_) {
        case OutputFormat::jsonl: {
            // Appended: on `"[" + std::string` GCC 12 at -O2 and above gives a false -Wrestrict
            // warning.
            const auto array = [](std::initializer_list<double> values) {
                std::string text(1, '[');
                for (const double value : values) {
                    if (text.size() > 1) text.push_back(',');
                    text += number(value);
                }
                text.push_back(']');
                return text;
            };
            const auto pair = [&array](cv::Point2d p) { return array({p.x, p.y}); };
            line = "{\"frame\":" + std::to_string(r.frame) + ",\"t\":" + number(seconds) +
                   ",\"state\":\"" + state +
                   "\",\"centroid\":" + (r.has_target ? pair(r.centroid) : "null") +
                   ",\"area\":" + (r.has_target && r.area ? number(*r.area) : "null") +
                   ",\"inner\":" + (r.has_target ? pair(r.inner) : "null") + ",\"position\":" +
                   (r.has_position ? array({r.position.x, r.position.y, r.position.z}) : "null") +
                   ",\"movement\":" + std::to_string(movement) +
                   ",\"us\":" + std::to_string(microseconds) + "}\n";
            break;
        }
        case OutputFormat::csv: {
            const auto optional = [](bool present, double value) {
                return present ? number(value) : std::string();
            };
            line = std::to_string(r.frame) + "," + number(seconds) + "," + state + "," +
                   optional(r.has_target, r.centroid.x) + "," +
                   optional(r.has_target, r.centroid.y) + "," +
                   optional(r.has_target && r.area, r.area.value_or(0.0)) + "," +
                   optional(r.has_target, r.inner.x) + "," + optional(r.has_target, r.inner.y) +
                   "," + optional(r.has_position, r.position.x) + "," +
                   optional(r.has_position, r.position.y) + "," +
                   optional(r.has_position, r.position.z) + "," + std::to_string(movement) + "," +
                   std::to_string(microseconds) + "\n";
            break;
        }
    }
    std::fputs(line.c_str(), out_);
}

}  // namespace raypoint::daemon
