// SPDX-License-Identifier: MIT
#pragma once
// What every clip of the click gesture set shares: the conditions drawn for it, the target's
// entry, the timing around it. Used by gesture_set.cpp (pushes, non-push motion) and
// button_gestures.cpp (right click, double click, scroll).

#include <functional>
#include <numbers>
#include <string>

#include "raypoint/scene/gesture_set.hpp"
#include "rng.hpp"

namespace raypoint::scene::gesture {

inline constexpr double sphere_size_m = 0.15;  // as the presets: a ball on a thread
inline constexpr double hand_size_m = 0.19;    // an adult hand
inline constexpr double entry_seconds = 0.8;   // from outside the right edge to the path
// Clicks are allowed 1 s (min_tracking_seconds) after the target is picked, just after it
// starts entering; pushes and counted motion start after that and a moment to settle.
inline constexpr double settle_seconds = 1.6;
inline constexpr double key_step = 0.02;  // s between keyframes: fine enough for a 0.15 s swipe
inline constexpr double pi = std::numbers::pi;

double smoothstep(double u);

// Draws the conditions every clip has: target, background, frame rate and camera.
GestureClip conditioned(Rng& rng, std::string name, bool hand);

// The path from `pose` sampled every key_step from the target's entry to the clip's end, sliding
// in from beyond the right edge over entry_seconds.
void sample_path(SceneSpec& s, const std::function<Keyframe(double)>& pose);

// Right click, double click and scroll clips: three gestures of `kind` each.
GestureClip button_clip(std::uint32_t seed, int index, GestureKind kind);

}  // namespace raypoint::scene::gesture
