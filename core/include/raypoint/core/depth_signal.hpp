// SPDX-License-Identifier: MIT
#pragma once
// The depth signal the click machine reads: the tracked target's scale, sqrt(area), with the
// steps that are not the target coming closer taken out. A push grows the target around a
// steady centroid; when the tracker's region takes in something else (or drops it), the size
// steps by 10-70% in one frame and the centroid jumps with it, and the new size may stay.
// Such a step is absorbed: the signal keeps its previous value and follows the new level's
// changes from there, so neither a one-frame glitch nor a step that stays reads as a push.
// When the centroid is back where it was on the next frame (glitch_return of the way), the
// step is given back: the size that stays up with the centroid back in place is a push whose
// frame blurred (at 10 fps a push of 0.25 s is one frame), and a size back too was a one-frame
// glitch. A piece that leaves again later, within glitch_return_seconds, the size stepping
// back the other way with the centroid back, has that step absorbed too: the push's level
// stands. A frame whose step the frame interval let through (at 10 fps, 3x glitch_step) with
// its centroid jumping, followed by the centroid back where it was, was a leak: the step back
// is not absorbed, or the leak's size would stay in the signal. A step faster than any push
// (glitch_leap per 1/30 s), and a step of glitch_step on a frame whose light jumped (glitch_light),
// are absorbed whatever the centroid does, and never given back.
//
// Pure: no allocation, no exceptions.

#include <optional>

#include <opencv2/core.hpp>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

class DepthSignal {
  public:
    explicit DepthSignal(const ClickSettings& settings) noexcept : settings_(settings) {}

    // scale: sqrt(area) this frame, or nullopt without a target (which starts over).
    // centroid: the tracker's raw centroid this frame, frame widths on both axes.
    // Returns the scale with the region's steps taken out; nullopt without a target.
    // timestamp: the frame's; glitch_step is per 1/30 s, scaled up for frames further apart.
    // light_change: the frame's (FrameResult::light_change); a step of glitch_step with the
    // light changed by glitch_light is the outline changing with the light.
    std::optional<double> update(std::optional<double> scale, cv::Point2d centroid,
                                 Timestamp timestamp = 0, double light_change = 0.0) noexcept;

    // Whether the last update absorbed a step.
    bool absorbed() const noexcept { return absorbed_; }
    // Whether the last update gave back the step absorbed on the frame before: the size
    // changed then, not now.
    bool given_back() const noexcept { return given_back_; }
    // Whether the centroid jumped on the last update by glitch_jump of the size (per 1/30 s),
    // whatever the size did: the region changing shape, or the target setting off sideways.
    bool jumped() const noexcept { return jumped_; }
    // Whether the size stepped on the last update by glitch_step with a centroid jump of
    // glitch_jump of the size, both per frame whatever the interval: at 30 fps and faster the
    // steps absorbed() takes out, at 10 fps also those its allowance for a push leaves in.
    bool stepped() const noexcept { return stepped_; }
    void reset() noexcept;

  private:
    // Whether the centroid is back glitch_return of its jump from where it was before the
    // pending step.
    bool returned(cv::Point2d centroid) const noexcept;
    // Whether `centroid` is within (1 - glitch_return) of `jump` (frame widths) of `where`.
    bool back_to(cv::Point2d centroid, cv::Point2d where, double jump) const noexcept;
    // Whether this frame undoes the frame before's step, which was left in: back the other way,
    // the centroid or the size back where it was two frames ago (DepthSignal::update).
    bool leak_ended(double scale, cv::Point2d centroid, double moved) const noexcept;

    ClickSettings settings_;
    double previous_ = 0.0;        // the raw scale of the previous frame; 0: none
    Timestamp previous_time_ = 0;  // the previous frame's timestamp
    cv::Point2d previous_centroid_;
    double before_previous_ = 0.0;  // the raw scale two frames back; 0: none, or its step was
                                    // taken out or given back
    cv::Point2d before_previous_centroid_;
    double gain_ = 1.0;  // signal = raw scale x gain; each absorbed step rescales it
    // The step absorbed on the previous frame: the centroid, scale and gain before it. When
    // the centroid is back the next frame, the jump was the centroid's alone (a blurred
    // frame, at 10 fps a push's own frame) and the step is given back.
    bool pending_ = false;
    bool pending_seen_ = false;   // the frame after the step has been seen
    Timestamp pending_time_ = 0;  // the step's frame
    bool rose_ = false;           // the step was up
    cv::Point2d before_centroid_;
    double before_gain_ = 1.0;
    double before_jump_ = 0.0;  // the centroid's jump with the step, frame widths
    bool absorbed_ = false;
    bool given_back_ = false;
    bool jumped_ = false;
    bool stepped_ = false;
};

}  // namespace raypoint::core
