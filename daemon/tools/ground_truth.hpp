// SPDX-License-Identifier: MIT
#pragma once
// The ground truth of a scene folder (raypoint-render-scene's output; docs/scoring.md, "What is
// scored: a scene folder"): truth.jsonl, one line a frame, and masks.npz, the target's visible
// pixels.

#include <filesystem>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/scene/truth.hpp"

namespace raypoint::daemon {

struct GroundTruth {
    std::vector<scene::Truth> truth;  // one a frame, in frame order
    std::vector<cv::Mat> masks;       // CV_8U, 255 on the target, at masks.npz's own size
};

// The truth in `folder`, or nothing when it has no truth.jsonl. At most `max_frames` frames
// (0: all). Throws InputError naming the file and line when truth.jsonl is malformed, or when
// masks.npz is missing, unreadable or does not have one mask a truth line.
std::optional<GroundTruth> read_ground_truth(const std::filesystem::path& folder, int max_frames);

}  // namespace raypoint::daemon
