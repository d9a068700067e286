// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint bench [CLIP...]`: raypoint's core (each estimator) against OpenCV's CamShift, KCF,
// CSRT and MIL on the same decoded frames: microseconds a frame (median, p95, ratio to the
// configured estimator) and accuracy by the scoring method (docs/scoring.md). Without CLIP, the
// project's rendered scenes.
int bench_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
