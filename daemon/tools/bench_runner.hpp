// SPDX-License-Identifier: MIT
#pragma once
// Runs raypoint's core and the OpenCV peers over one clip's decoded frames: the time each
// spends a frame and, when the clip has ground truth, its accuracy by the scoring method
// (docs/scoring.md).

#include <optional>
#include <string>
#include <vector>

#include "bench_clip.hpp"
#include "peer_trackers.hpp"
#include "raypoint/core/settings.hpp"
#include "raypoint/scene/evaluation.hpp"

namespace raypoint::daemon {

struct SystemResult {
    std::string system;
    std::vector<double> microseconds;  // one a timed frame
    std::optional<scene::Evaluation> accuracy;
    std::string error;  // a peer that threw (an OpenCV assertion): a row, not a crash
};

// Where the peers start. With truth, the scoring method's rule: the first frame where the target is
// present and moving, from its true box. Without truth (timing only), frame 0 and a centred box
// of a fifth of the frame each way.
struct PeerStart {
    int frame = 0;
    cv::Rect box;
};
PeerStart peer_start(const BenchClip& clip);

// Each system is timed on the frames after the peers' start (the peers' first frame is spent on
// init), so all rows measure the same frames. raypoint runs every frame, as it would live.
SystemResult run_raypoint(const BenchClip& clip, const core::Settings& settings,
                          const PeerStart& start);
SystemResult run_peer(const BenchClip& clip, PeerKind kind, const PeerStart& start);

}  // namespace raypoint::daemon
