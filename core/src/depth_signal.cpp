// SPDX-License-Identifier: MIT
#include "raypoint/core/depth_signal.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {

void DepthSignal::reset() noexcept {
    previous_ = 0.0;
    before_previous_ = 0.0;
    gain_ = 1.0;
    pending_ = false;
    given_back_ = false;
    absorbed_ = false;
}

bool DepthSignal::back_to(cv::Point2d centroid, cv::Point2d where, double jump) const noexcept {
    return cv::norm(centroid - where) <= (1.0 - settings_.glitch_return) * jump;
}

bool DepthSignal::returned(cv::Point2d centroid) const noexcept {
    return back_to(centroid, before_centroid_, before_jump_);
}

// The previous frame stepped by glitch_step or more and was left in, and this frame undoes it:
// its step goes the other way, and its centroid is back where it was before or its size within
// glitch_step of what it was (a region flickering between two shapes comes back to the size, not
// always to the same centroid). That frame was the glitch and this one is its end: taking this
// step out would keep the glitch's size in the signal until it starts over. Two ways a glitch is
// left in: at 10 fps its interval's allowance (glitch_step per 1/30 s) lets a leak's +20% pass; at
// any rate a piece lost for one frame can move the centroid just under glitch_jump of the larger
// size, and its return, measured against the smaller one, just over it.
bool DepthSignal::leak_ended(double scale, cv::Point2d centroid, double moved) const noexcept {
    return before_previous_ > 0.0 &&
           std::abs(previous_ / before_previous_ - 1.0) >= settings_.glitch_step &&
           (scale > previous_) == (previous_ < before_previous_) &&
           (back_to(centroid, before_previous_centroid_, moved) ||
            std::abs(scale / before_previous_ - 1.0) < settings_.glitch_step);
}

std::optional<double> DepthSignal::update(std::optional<double> scale, cv::Point2d centroid,
                                          Timestamp timestamp, double light_change) noexcept {
    const Timestamp previous_time = previous_time_;
    previous_time_ = timestamp;
    absorbed_ = false;
    given_back_ = false;
    jumped_ = false;
    stepped_ = false;
    if (!scale || !(*scale > 0.0)) {
        reset();
        return std::nullopt;
    }
    // The time since the last frame in frames 1/30 s apart.
    const double interval = static_cast<double>(timestamp - previous_time) / (1e6 / 30.0);
    // glitch_step is a step between frames 1/30 s apart: a push brings the target closer by
    // three times as much between frames at 10 fps (a quick push is 2-3 frames there).
    const double frames = std::max(1.0, interval);
    // The step absorbed on the frame before, or within glitch_return_seconds before.
    const bool next = pending_ && !pending_seen_;
    const bool later =
        pending_ && pending_seen_ &&
        static_cast<double>(timestamp - pending_time_) <= settings_.glitch_return_seconds * 1e6;
    pending_ = next || later;
    pending_seen_ = true;
    if (next && returned(centroid)) {
        gain_ = before_gain_;  // the centroid is back: whatever the size does now is the target's
        given_back_ = true;
        pending_ = false;
    } else if (later && returned(centroid) && (*scale < previous_) == rose_) {
        // The piece has left again, frames later: its step is taken out as its arrival was.
        // Not given back: the push may have gone on meanwhile, and a region that keeps a piece
        // can still bring its centroid back.
        gain_ *= previous_ / *scale;
        absorbed_ = true;
        pending_ = false;
    } else if (previous_ > 0.0 && (settings_.glitch_jump > 0.0 || settings_.glitch_leap > 0.0 ||
                                   settings_.glitch_light > 0.0)) {
        const double step = *scale / previous_ - 1.0;
        // The centroid's jump in units of the target's size: a push about a steady centroid
        // moves it little (the gesture set's pushes: a median 0.01 of the size a frame), a
        // region that takes in or drops a piece moves it by about the piece's share.
        const double moved = cv::norm(centroid - previous_centroid_);  // frame widths
        const double jump = moved / previous_;
        // At 10 fps a push's own centroid drifts three times as far between frames.
        jumped_ = settings_.glitch_jump > 0.0 && jump >= settings_.glitch_jump * frames;
        // A step of glitch_step with a centroid jump of glitch_jump, between the two frames
        // whatever their interval: a held push does not grow, so at 10 fps too such a step is
        // the region changing, though a push's step that size between those frames is left in.
        stepped_ = settings_.glitch_jump > 0.0 && std::abs(step) >= settings_.glitch_step &&
                   jump >= settings_.glitch_jump;
        const bool large = std::abs(step) >= settings_.glitch_step * frames;
        // The same step against the frame interval's allowance for a push (frames >= 1, so
        // large implies the step of stepped_): taken out.
        const bool shifted = stepped_ && large;
        // Faster than any push, whatever the centroid: a piece taken in straight above or
        // below the centroid hardly moves it. Per the frame's own interval, 60 fps included.
        const bool leap = settings_.glitch_leap > 0.0 && interval > 0.0 &&
                          std::abs(step) >= settings_.glitch_leap * interval;
        // A camera's gain or exposure jump moves the outline's weak edges: the region steps
        // with the light, on that frame, and the centroid need not move.
        const bool relit =
            settings_.glitch_light > 0.0 && light_change >= settings_.glitch_light && large;
        if ((shifted || leap || relit) && !leak_ended(*scale, centroid, moved)) {
            // Given back when the centroid comes back: only a step whose centroid jumped can
            // show that it was the centroid's alone (a still centroid is always "back").
            pending_ = shifted;
            pending_seen_ = false;
            rose_ = step > 0.0;
            pending_time_ = timestamp;
            before_centroid_ = previous_centroid_;
            before_gain_ = gain_;
            before_jump_ = moved;
            gain_ *= previous_ / *scale;
            absorbed_ = true;
        }
    }
    // A frame whose step was taken out or given back is no leak's frame before.
    before_previous_ = absorbed_ || given_back_ ? 0.0 : previous_;
    before_previous_centroid_ = previous_centroid_;
    previous_ = *scale;
    previous_centroid_ = centroid;
    return *scale * gain_;
}

}  // namespace raypoint::core
