// SPDX-License-Identifier: MIT
#pragma once
// `raypoint plot TRACK.jsonl -o OUT.png [--events FILE]`: x, y, z and the state band over time.

#include <span>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

#include "raypoint/view/track_log.hpp"

namespace raypoint::daemon {

int plot_command(std::span<const std::string_view> args);

// Writes `picture` as PNG (or JPEG, by the name's extension); throws InputError naming `path` when
// it cannot.
void write_png(const cv::Mat& picture, const std::string& path);

// Draws `log` and writes the PNG; throws InputError naming `path` when it cannot be written.
void write_plot(const view::TrackLog& log, const std::string& path);

}  // namespace raypoint::daemon
