// SPDX-License-Identifier: MIT
#include "bench_runner.hpp"

#include <chrono>
#include <cmath>

#include "raypoint/core/tracker.hpp"

namespace raypoint::daemon {
namespace {

using Clock = std::chrono::steady_clock;

double microseconds_since(Clock::time_point begin) {
    return std::chrono::duration<double, std::micro>(Clock::now() - begin).count();
}

// A peer's box as the scoring method reports it: its centre as the centroid, no area, and the
// square root of its area in pixels as the depth cue (which correlates with 1 / depth when it
// works).
core::FrameResult peer_result(const std::optional<cv::Rect>& box, cv::Size frame) {
    core::FrameResult result;
    if (!box) return result;
    result.has_target = true;
    result.centroid = {(box->x + box->width / 2.0) / frame.width,
                       (box->y + box->height / 2.0) / frame.height};
    result.has_position = true;
    result.position.z = std::sqrt(std::max(0.0, static_cast<double>(box->area())));
    return result;
}

// Truth lines past the last decoded frame count as frames without an answer, as in the scoring
// method.
void finish(const BenchClip& clip, scene::Evaluator& evaluator, SystemResult& out) {
    if (!clip.truth) return;
    for (std::size_t i = clip.frames.size(); i < clip.truth->truth.size(); ++i)
        evaluator.add(clip.truth->truth[i], clip.truth->masks[i], core::FrameResult{});
    out.accuracy = evaluator.result();
}

}  // namespace

PeerStart peer_start(const BenchClip& clip) {
    const cv::Size size = clip.frames.front().bgr.size();
    if (clip.truth) {
        const auto& truth = clip.truth->truth;
        for (std::size_t i = 0; i < truth.size() && i < clip.frames.size(); ++i) {
            const scene::Truth& t = truth[i];
            if (!t.present || !t.moving) continue;
            // int() of the pixel box, as the scoring method passes it.
            return {static_cast<int>(i), cv::Rect(static_cast<int>(t.bx * size.width),
                                                  static_cast<int>(t.by * size.height),
                                                  static_cast<int>(t.bw * size.width),
                                                  static_cast<int>(t.bh * size.height))};
        }
    }
    return {0, cv::Rect(size.width * 2 / 5, size.height * 2 / 5, size.width / 5, size.height / 5)};
}

SystemResult run_raypoint(const BenchClip& clip, const core::Settings& settings,
                          const PeerStart& start) {
    SystemResult out;
    out.system = "raypoint " + std::string(core::to_string(settings.estimator.kind));
    core::Tracker tracker(settings);
    scene::Evaluator evaluator;
    out.microseconds.reserve(clip.frames.size());
    for (std::size_t i = 0; i < clip.frames.size(); ++i) {
        const DecodedFrame& frame = clip.frames[i];
        const core::FrameView view{frame.bgr.data,         frame.bgr.cols,
                                   frame.bgr.rows,         static_cast<int>(frame.bgr.step),
                                   core::PixelFormat::bgr, frame.timestamp};
        const auto begin = Clock::now();
        const core::FrameResult result = tracker.process(view);
        const double us = microseconds_since(begin);
        if (static_cast<int>(i) > start.frame) out.microseconds.push_back(us);
        if (clip.truth && i < clip.truth->truth.size()) {
            evaluator.add(clip.truth->truth[i], clip.truth->masks[i], result);
        }
    }
    finish(clip, evaluator, out);
    return out;
}

SystemResult run_peer(const BenchClip& clip, PeerKind kind, const PeerStart& start) {
    SystemResult out;
    out.system = std::string(to_string(kind));
    scene::Evaluator evaluator;
    try {
        const auto peer = make_peer(kind);
        for (std::size_t i = 0; i < clip.frames.size(); ++i) {
            const cv::Mat& bgr = clip.frames[i].bgr;
            std::optional<cv::Rect> box;
            if (static_cast<int>(i) == start.frame) {
                peer->init(bgr, start.box);
            } else if (static_cast<int>(i) > start.frame) {
                const auto begin = Clock::now();
                box = peer->update(bgr);
                out.microseconds.push_back(microseconds_since(begin));
            }
            if (clip.truth && i < clip.truth->truth.size()) {
                evaluator.add(clip.truth->truth[i], clip.truth->masks[i],
                              peer_result(box, bgr.size()));
            }
        }
    } catch (const cv::Exception& e) {
        // OpenCV's messages span lines; the table has one.
        out.error = e.msg.substr(0, e.msg.find('\n'));
        out.microseconds.clear();
        return out;
    }
    finish(clip, evaluator, out);
    return out;
}

}  // namespace raypoint::daemon
