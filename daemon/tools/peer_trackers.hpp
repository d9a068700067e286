// SPDX-License-Identifier: MIT
#pragma once
// What a user could run instead of raypoint: OpenCV's CamShift (hue back-projection, as in
// OpenCV's camshift sample), KCF and CSRT (contrib tracking) and MIL (video). Each is given
// the target's box on its first frame, as the scoring method starts them (docs/scoring.md).

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

namespace raypoint::daemon {

enum class PeerKind { camshift, kcf, csrt, mil };

std::string_view to_string(PeerKind kind) noexcept;
bool peer_from_string(std::string_view name, PeerKind& kind) noexcept;
std::vector<PeerKind> all_peers();

class PeerTracker {
  public:
    virtual ~PeerTracker() = default;
    // `box` in frame pixels, on a CV_8UC3 BGR frame.
    virtual void init(const cv::Mat& bgr, const cv::Rect& box) = 0;
    // The target's box in the next frame, or nothing when the tracker reports a failure. Any
    // colour conversion the tracker needs happens here, so it is timed with it.
    virtual std::optional<cv::Rect> update(const cv::Mat& bgr) = 0;
};

std::unique_ptr<PeerTracker> make_peer(PeerKind kind);

}  // namespace raypoint::daemon
