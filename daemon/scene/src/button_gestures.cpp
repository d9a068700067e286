// SPDX-License-Identifier: MIT
// The gesture set's right clicks, double clicks and scrolls (gesture_set.hpp): the same
// conditions and drift as the push clips, three gestures a clip.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gesture_parts.hpp"

namespace raypoint::scene::gesture {
namespace {

// Pushes of these gestures bring the target 15-40% closer within 0.15-0.6 s: the pushes a left
// click is measured on (docs/clicks.md), so a miss is the gesture's, not the push's.
struct PushDraw {
    double depth, seconds;
};

PushDraw draw_push(Rng& rng, double longest = 0.6) {
    return {rng.uniform(0.15, 0.40), rng.uniform(0.15, longest)};
}

// A vertical move while a push is held (scroll): y changes by dy from `from` to `to`.
struct Slide {
    double from, to, dy;
};

}  // namespace

GestureClip button_clip(std::uint32_t seed, int index, GestureKind kind) {
    const bool right = kind == GestureKind::right;
    const bool twice = kind == GestureKind::double_click;
    const char* stem = right ? "right" : twice ? "double" : "scroll";
    const std::uint64_t salt = right ? 20000 : twice ? 21000 : 22000;
    Rng rng(mix_seed(seed, salt + static_cast<std::uint64_t>(index)));
    const bool hand = rng.chance(0.6);
    char name[32];
    std::snprintf(name, sizeof name, "%s-%03d", stem, index);
    GestureClip clip = conditioned(rng, name, hand);
    clip.motion = stem;
    SceneSpec& s = clip.spec;
    const double d0 = hand ? rng.uniform(0.6, 0.85) : rng.uniform(0.5, 0.75);
    const double x0 = rng.uniform(0.38, 0.62);
    const double y0 = rng.uniform(0.4, 0.6);
    const double phase = rng.uniform(0, 2 * pi);
    double t = s.empty_seconds + settle_seconds + rng.uniform(0.8, 1.4);
    std::vector<Slide> slides;
    double y_now = y0;
    for (int k = 0; k < 3; ++k) {
        IntendedClick gesture;
        gesture.start = t;
        if (twice) {
            // Two quick pushes, the second 0.3-0.5 s after the first is back out: a double
            // click's pace, with each push as quick as a click's.
            const PushDraw first = draw_push(rng, 0.3);
            const PushDraw second = draw_push(rng, 0.3);
            const double hold1 = rng.uniform(0.0, 0.1);
            const double hold2 = rng.uniform(0.0, 0.1);
            const double t2 = t + 2 * first.seconds + hold1 + rng.uniform(0.3, 0.5);
            s.shaped_pushes.push_back({t, first.depth, first.seconds, hold1});
            s.shaped_pushes.push_back({t2, second.depth, second.seconds, hold2});
            gesture.kind = GestureKind::double_click;
            gesture.press = t2 + second.seconds / 2;
            gesture.release = t2 + second.seconds * 1.5 + hold2;
            gesture.depth = std::min(first.depth, second.depth);
            gesture.seconds = std::max(first.seconds, second.seconds);
            t = t2 + 2 * second.seconds + hold2;
        } else {
            const PushDraw push = draw_push(rng);
            // Right: held still 0.9-1.4 s. Scroll: held 1.0-1.6 s, moving 12-20% of the
            // frame's height up or down from 0.15 s after the push is in to 0.2 s before it
            // goes back out.
            const double hold = right ? rng.uniform(0.9, 1.4) : rng.uniform(1.0, 1.6);
            s.shaped_pushes.push_back({t, push.depth, push.seconds, hold});
            gesture.depth = push.depth;
            gesture.seconds = push.seconds;
            gesture.release = t + push.seconds * 1.5 + hold;
            if (right) {
                gesture.kind = GestureKind::right;
                gesture.press = t + push.seconds + hold / 2;
            } else {
                double dy = rng.uniform(0.12, 0.2) * (rng.chance(0.5) ? -1 : 1);
                if (y_now + dy < 0.28 || y_now + dy > 0.72) dy = -dy;
                y_now += dy;
                slides.push_back({t + push.seconds + 0.15, t + push.seconds + hold - 0.2, dy});
                gesture.kind = dy < 0 ? GestureKind::scroll_up : GestureKind::scroll_down;
                gesture.press = t + push.seconds / 2;
            }
            t += 2 * push.seconds + hold;
        }
        clip.clicks.push_back(gesture);
        t += rng.uniform(1.2, 1.8);
    }
    s.seconds = t;
    sample_path(s, [&](double when) {
        Keyframe key;
        key.x = x0 + 0.012 * std::sin(0.9 * when + phase);
        key.y = y0 + 0.01 * std::sin(0.7 * when + 2 * phase);
        for (const Slide& slide : slides)
            key.y += slide.dy * smoothstep((when - slide.from) / (slide.to - slide.from));
        key.depth = d0 * (1 + 0.015 * std::sin(0.5 * when + 3 * phase));
        return key;
    });
    return clip;
}

}  // namespace raypoint::scene::gesture
