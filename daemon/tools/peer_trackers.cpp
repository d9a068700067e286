// SPDX-License-Identifier: MIT
#include "peer_trackers.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/tracking.hpp>
#include <opencv2/video/tracking.hpp>

namespace raypoint::daemon {
namespace {

// The scoring method's CamShift (docs/scoring.md): a 16-bin hue histogram of the first box (pixels
// with saturation >= 30 and value >= 20), back-projected on every frame, masked the same way, then
// CamShift with at most 10 iterations or 1 px of movement.
class CamShiftPeer final : public PeerTracker {
  public:
    void init(const cv::Mat& bgr, const cv::Rect& box) override {
        cv::cvtColor(bgr, hsv_, cv::COLOR_BGR2HSV);
        const cv::Rect clipped = box & cv::Rect(0, 0, bgr.cols, bgr.rows);
        const cv::Mat roi = hsv_(clipped);
        cv::Mat mask;
        cv::inRange(roi, low, high, mask);
        const int channel = 0;
        const int bins = hue_bins;
        const float hue_range[] = {0.0F, 180.0F};
        const float* ranges[] = {hue_range};
        cv::calcHist(&roi, 1, &channel, mask, histogram_, 1, &bins, ranges);
        cv::normalize(histogram_, histogram_, 0, 255, cv::NORM_MINMAX);
        window_ = cv::Rect(box.x, box.y, std::max(1, box.width), std::max(1, box.height));
    }

    std::optional<cv::Rect> update(const cv::Mat& bgr) override {
        cv::cvtColor(bgr, hsv_, cv::COLOR_BGR2HSV);
        const int channel = 0;
        const float hue_range[] = {0.0F, 180.0F};
        const float* ranges[] = {hue_range};
        cv::calcBackProject(&hsv_, 1, &channel, histogram_, backprojection_, ranges, 1.0);
        cv::inRange(hsv_, low, high, mask_);
        cv::bitwise_and(backprojection_, mask_, backprojection_);
        cv::CamShift(backprojection_, window_,
                     cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 10, 1));
        if (window_.width <= 0 || window_.height <= 0) {
            window_ = cv::Rect(0, 0, bgr.cols, bgr.rows);
            return std::nullopt;
        }
        return window_;
    }

  private:
    static constexpr int hue_bins = 16;
    inline static const cv::Scalar low{0, 30, 20};
    inline static const cv::Scalar high{180, 255, 255};
    cv::Mat hsv_, mask_, backprojection_, histogram_;
    cv::Rect window_;
};

// KCF, CSRT and MIL share cv::Tracker's interface.
class OpenCvPeer final : public PeerTracker {
  public:
    explicit OpenCvPeer(cv::Ptr<cv::Tracker> tracker) : tracker_(std::move(tracker)) {}

    void init(const cv::Mat& bgr, const cv::Rect& box) override { tracker_->init(bgr, box); }

    std::optional<cv::Rect> update(const cv::Mat& bgr) override {
        cv::Rect box;
        if (!tracker_->update(bgr, box)) return std::nullopt;
        return box;
    }

  private:
    cv::Ptr<cv::Tracker> tracker_;
};

}  // namespace

std::string_view to_string(PeerKind kind) noexcept {
    switch (kind) {
        case PeerKind::camshift:
            return "camshift";
        case PeerKind::kcf:
            return "kcf";
        case PeerKind::csrt:
            return "csrt";
        case PeerKind::mil:
            return "mil";
    }
    return "?";
}

bool peer_from_string(std::string_view name, PeerKind& kind) noexcept {
    for (const PeerKind candidate : all_peers()) {
        if (to_string(candidate) == name) {
            kind = candidate;
            return true;
        }
    }
    return false;
}

std::vector<PeerKind> all_peers() {
    return {PeerKind::camshift, PeerKind::kcf, PeerKind::csrt, PeerKind::mil};
}

std::unique_ptr<PeerTracker> make_peer(PeerKind kind) {
    switch (kind) {
        case PeerKind::camshift:
            return std::make_unique<CamShiftPeer>();
        case PeerKind::kcf:
            return std::make_unique<OpenCvPeer>(cv::TrackerKCF::create());
        case PeerKind::csrt:
            return std::make_unique<OpenCvPeer>(cv::TrackerCSRT::create());
        case PeerKind::mil:
            return std::make_unique<OpenCvPeer>(cv::TrackerMIL::create());
    }
    return nullptr;
}

}  // namespace raypoint::daemon
