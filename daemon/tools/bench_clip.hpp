// SPDX-License-Identifier: MIT
#pragma once
// The clips `raypoint bench` measures on: every frame decoded (or rendered) into memory before
// any timing, with the ground truth when there is one.

#include <optional>
#include <string>
#include <vector>

#include "ground_truth.hpp"
#include "video_source.hpp"

namespace raypoint::daemon {

struct BenchClip {
    std::string name;
    std::vector<DecodedFrame> frames;
    std::optional<GroundTruth> truth;  // nothing: timing only
};

// A video file (with the truth beside it when its folder has a truth.jsonl) or a scene folder
// holding video.mp4 (a scene folder, docs/scoring.md). At most `max_frames` frames (0: all).
// Throws InputError.
BenchClip load_clip(const std::string& argument, int max_frames);

// What load_clip would throw for this argument, found by opening the video and reading the
// truth's first lines, without decoding: to fail before minutes spent on other clips.
void check_clip(const std::string& argument);

// A preset of the project's scene renderer (tests/scene), rendered in memory with its exact
// truth and masks. Throws UsageError for an unknown preset.
BenchClip render_clip(const std::string& preset, int max_frames);

}  // namespace raypoint::daemon
