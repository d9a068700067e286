// SPDX-License-Identifier: MIT
#pragma once
// The click gesture set: clips of pushes toward the camera drawn from ranges (depth, duration,
// hold, target, background, frame rate, camera) and clips of motion that must never click
// (leaning in, walking closer, fast swipes, turning the hand, leaving and re-entering,
// brightness jumps, ordinary wandering), each with the truth of its intended presses and
// releases. Seeded: the same name and seed give the same clips. `raypoint eval-clicks` runs the
// pointer on them (docs/clicks.md).

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

enum class GestureKind {
    click,  // push, pull back within a moment
    drag,   // push, hold while moving sideways, pull back
    // The optional gestures (click.right_seconds, double_seconds, scroll_gain):
    right,         // push, hold still, pull back
    double_click,  // two quick pushes
    scroll_up,     // push, move up while held, pull back
    scroll_down,   // push, move down while held, pull back
};

std::string_view to_string(GestureKind kind);

// One intended press and release. Times in seconds of the clip.
struct IntendedClick {
    GestureKind kind = GestureKind::click;
    double start = 0;    // the target starts coming closer (a double click: the first push)
    double press = 0;    // halfway in: where a press is meant (a double click: the second)
    double release = 0;  // halfway back out: where the release is meant
    double depth = 0;    // relative: 0.2 = the target came 20% closer (0 when unknown)
    double seconds = 0;  // the push's duration in (0 when unknown)
};

struct GestureClip {
    SceneSpec spec;
    // "push", "right", "double", "scroll", or the motion that must never click: lean, walk, swipe,
    // turn, reenter, brightness, wander.
    std::string motion;
    // Conditions for the per-condition table, in this order: target, background, fps, camera.
    std::vector<std::pair<std::string, std::string>> conditions;
    std::vector<IntendedClick> clicks;  // sorted by start
    // The spans of non-push motion counted for false clicks (from when clicks are allowed, less
    // the approaches); none for push clips.
    std::vector<std::pair<double, double>> motion_spans;
    // Spans of a motion clip in which its path comes closer as fast as a push
    // (target_push_depth within target_push_seconds, approaches.hpp): a press there is neither
    // false nor a push's.
    std::vector<std::pair<double, double>> approaches;
};

// The pushes the set's targets are stated for: at least 15% closer within 0.6 s.
inline constexpr double target_push_depth = 0.15;
inline constexpr double target_push_seconds = 0.6;
// A press up to this long after such an approach answers it.
inline constexpr double approach_press_seconds = 0.3;

// "full": 110 push clips (330 pushes), 30 motion clips (about 11 minutes of non-push motion) and
// 20 clips each of right clicks, double clicks and scrolls (60 gestures each);
// "ci": a small fixed subset of the same kinds (6 push clips, 3 shorter motion clips, 2 clips
// of each of the other gestures).
// Throws std::invalid_argument for another name.
std::vector<GestureClip> gesture_set(std::string_view name, std::uint32_t seed = 1);

// The same clips in front of photographs (image files OpenCV reads): each clip's background is
// one of `photos`, chosen by the seed and the clip's place in the set; their condition
// "background" is "photo". Throws std::invalid_argument when `photos` is empty.
void use_photos(std::vector<GestureClip>& clips, const std::vector<std::string>& photos,
                std::uint32_t seed);

// The truth file beside a clip: one line a gesture,
// "click|drag|right|double|scroll_up|scroll_down START PRESS RELEASE [DEPTH SECONDS]", and "motion
// FROM TO" for a span of non-push motion; '#' starts a comment.
std::string click_truth_text(const GestureClip& clip);

}  // namespace raypoint::scene
