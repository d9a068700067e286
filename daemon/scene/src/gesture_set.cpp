// SPDX-License-Identifier: MIT
#include "raypoint/scene/gesture_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "gesture_parts.hpp"
#include "raypoint/scene/approaches.hpp"
#include "rng.hpp"
#include "sprite.hpp"

namespace raypoint::scene {

namespace gesture {

double smoothstep(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

// Draws the conditions every clip has: target, background, frame rate and camera.
GestureClip conditioned(Rng& rng, std::string name, bool hand) {
    GestureClip clip;
    SceneSpec& s = clip.spec;
    s.name = std::move(name);
    s.seed = static_cast<std::uint32_t>(rng.next());
    s.target = hand ? Target::hand : Target::sphere;
    s.target_size_m = hand ? hand_size_m : sphere_size_m;
    s.background = rng.chance(0.5) ? Background::plain : Background::cluttered;
    const double fps_draw = rng.uniform();
    s.fps = fps_draw < 0.2 ? 10 : fps_draw < 0.8 ? 30 : 60;
    const double camera_draw = rng.uniform();
    std::string camera = "clean";
    if (camera_draw < 0.25) {
        camera = "noisy";
        s.noise_sigma = 6;
        s.blur = 0.6;
    } else if (camera_draw < 0.5) {
        camera = "jpeg";
        s.noise_sigma = 2;
        s.jpeg_quality = 40;
    }
    if (s.fps == 10) s.blur = std::max(s.blur, 0.6);  // longer exposures at low frame rates
    clip.conditions = {{"target", hand ? "hand" : "sphere"},
                       {"background", s.background == Background::plain ? "plain" : "cluttered"},
                       {"fps", std::to_string(static_cast<int>(s.fps))},
                       {"camera", camera}};
    return clip;
}

// The path from `pose` sampled every key_step from the target's entry to the clip's end, sliding
// in from beyond the right edge over entry_seconds.
void sample_path(SceneSpec& s, const std::function<Keyframe(double)>& pose) {
    const double e = s.empty_seconds;
    s.path.clear();
    for (double t = e; t <= s.seconds + key_step; t += key_step) {
        Keyframe k = pose(t);
        const double u = smoothstep((t - e) / entry_seconds);
        k.x = 1.3 + (k.x - 1.3) * u;
        k.t = t;
        s.path.push_back(k);
    }
}

}  // namespace gesture

namespace {

using gesture::conditioned;
using gesture::hand_size_m;
using gesture::pi;
using gesture::sample_path;
using gesture::settle_seconds;
using gesture::smoothstep;

GestureClip push_clip(std::uint32_t seed, int index) {
    Rng rng(mix_seed(seed, 1000 + static_cast<std::uint64_t>(index)));
    const bool hand = rng.chance(0.6);
    char name[32];
    std::snprintf(name, sizeof name, "push-%03d", index);
    GestureClip clip = conditioned(rng, name, hand);
    clip.motion = "push";
    SceneSpec& s = clip.spec;
    const double d0 = hand ? rng.uniform(0.6, 0.85) : rng.uniform(0.5, 0.75);
    const double x0 = rng.uniform(0.38, 0.62);
    const double y0 = rng.uniform(0.4, 0.6);
    const double phase = rng.uniform(0, 2 * pi);
    // The tracker starts up for 2 s, picks the target as it enters and allows clicks 1 s
    // later: a user sees the cursor follow before pushing.
    double t = s.empty_seconds + settle_seconds + rng.uniform(0.8, 1.4);
    struct Slide {
        double from, to, dx;
    };
    std::vector<Slide> slides;  // drags move sideways while held
    double x_now = x0;
    for (int k = 0; k < 3; ++k) {
        SceneSpec::Push push;
        push.start = t;
        push.depth = rng.uniform(0.08, 0.40);
        push.seconds = rng.uniform(0.15, 0.8);
        const bool drag = rng.chance(0.25);
        push.hold = drag ? rng.uniform(1.2, 2.0) : rng.uniform(0.0, 0.2);
        s.shaped_pushes.push_back(push);
        IntendedClick click;
        click.kind = drag ? GestureKind::drag : GestureKind::click;
        click.start = t;
        click.press = t + push.seconds / 2;
        click.release = t + push.seconds * 1.5 + push.hold;
        click.depth = push.depth;
        click.seconds = push.seconds;
        clip.clicks.push_back(click);
        if (drag) {
            const double dx = (x_now > 0.5 ? -1 : 1) * rng.uniform(0.08, 0.15);
            slides.push_back({t + push.seconds + 0.15, t + push.seconds + push.hold - 0.15, dx});
            x_now += dx;
        }
        t += 2 * push.seconds + push.hold + rng.uniform(1.2, 1.8);
    }
    s.seconds = t;
    sample_path(s, [&](double when) {
        Keyframe k;
        // A hand in the air is never quite still: a slow drift of about a centimetre.
        k.x = x0 + 0.012 * std::sin(0.9 * when + phase);
        for (const Slide& slide : slides)
            k.x += slide.dx * smoothstep((when - slide.from) / (slide.to - slide.from));
        k.y = y0 + 0.01 * std::sin(0.7 * when + 2 * phase);
        k.depth = d0 * (1 + 0.015 * std::sin(0.5 * when + 3 * phase));
        return k;
    });
    return clip;
}

// Repeats `episode` (given the time into it and its index) every `period` seconds from `from`.
double cycle(double t, double from, double period, int& index) {
    const double u = std::max(0.0, t - from);
    index = static_cast<int>(u / period);
    return u - index * period;
}

GestureClip motion_clip(std::uint32_t seed, int index, const std::string& motion, double seconds) {
    Rng rng(mix_seed(seed, 5000 + static_cast<std::uint64_t>(index)));
    const bool hand =
        motion == "turn" || motion == "fingers" || motion == "fist" || rng.chance(0.6);
    GestureClip clip = conditioned(rng, motion + "-" + std::to_string(index), hand);
    clip.motion = motion;
    SceneSpec& s = clip.spec;
    s.seconds = seconds;
    const double from = s.empty_seconds + settle_seconds;
    const double d0 = motion == "walk" ? rng.uniform(0.75, 0.9) : rng.uniform(0.55, 0.8);
    const double x0 = rng.uniform(0.4, 0.6);
    const double y0 = rng.uniform(0.42, 0.58);
    const double phase = rng.uniform(0, 2 * pi);
    const double rate = rng.uniform(0.8, 1.2);  // each user has a pace
    const double swing = rng.uniform(0.4, 0.8);
    std::function<Keyframe(double)> pose = [&](double t) {
        Keyframe k;
        k.x = x0 + 0.012 * std::sin(0.9 * t + phase);
        k.y = y0 + 0.01 * std::sin(0.7 * t + phase);
        k.depth = d0;
        return k;
    };
    if (motion == "lean") {
        // 20% closer over 2 s, a moment there, back over 2 s.
        pose = [&, base = pose](double t) {
            Keyframe k = base(t);
            int n = 0;
            const double u = cycle(t, from, 6.5 * rate, n) / rate;
            const double in = smoothstep(u / 2) - smoothstep((u - 3.5) / 2);
            k.depth = d0 * (1 - 0.2 * in);
            return k;
        };
    } else if (motion == "walk") {
        // 40% closer over 3 s with the bob of each step, then back.
        pose = [&, base = pose](double t) {
            Keyframe k = base(t);
            int n = 0;
            const double u = cycle(t, from, 8 * rate, n) / rate;
            const double in = smoothstep(u / 3) - smoothstep((u - 4) / 3);
            k.depth = d0 * (1 - 0.4 * in);
            const double walking = (u < 3 || (u > 4 && u < 7)) ? 1 : 0;
            k.y += walking * 0.015 * std::sin(2 * pi * 1.8 * t);
            k.x += walking * 0.01 * std::sin(2 * pi * 0.9 * t);
            return k;
        };
    } else if (motion == "swipe") {
        // Sideways across 40% of the frame in 0.15-0.25 s (2-3x an ordinary move), the arm's arc
        // bringing the hand up to 6% closer halfway.
        const double swipe = rng.uniform(0.15, 0.25);
        const double arc = rng.uniform(0.0, 0.06);
        pose = [&, base = pose, swipe, arc](double t) {
            Keyframe k = base(t);
            int n = 0;
            const double period = swipe + 0.9 * rate;
            const double u = cycle(t, from, period, n);
            const double v = smoothstep(u / swipe);
            const double left = 0.3;
            const double right = 0.7;
            k.x = n % 2 == 0 ? right + (left - right) * v : left + (right - left) * v;
            if (t < from) k.x = right;
            k.depth = d0 * (1 - arc * std::sin(pi * std::clamp(u / swipe, 0.0, 1.0)));
            return k;
        };
    } else if (motion == "turn") {
        // The hand turns by 0.4-0.8 rad in 0.3-0.6 s and back.
        const double turn = rng.uniform(0.3, 0.6);
        pose = [&, base = pose, turn](double t) {
            Keyframe k = base(t);
            int n = 0;
            const double u = cycle(t, from, 2 * turn + 0.8 * rate, n);
            k.angle = (n % 2 == 0 ? 1 : -1) * swing *
                      (smoothstep(u / turn) - smoothstep((u - turn - 0.4) / turn));
            return k;
        };
    } else if (motion == "reenter") {
        // Leaves by the side over 0.5 s, stays out 1-2 s, comes back over 0.6 s, stays 3 s.
        const double out = rng.uniform(1.0, 2.0);
        pose = [&, base = pose, out](double t) {
            Keyframe k = base(t);
            int n = 0;
            const double u = cycle(t, from + 1, 4.1 + out, n);
            const double gone =
                t < from + 1 ? 0 : smoothstep(u / 0.5) - smoothstep((u - 0.5 - out) / 0.6);
            const double edge = n % 2 == 0 ? 1.4 : -0.4;
            k.x += (edge - k.x) * gone;
            return k;
        };
    } else if (motion == "brightness") {
        // Ordinary slow moves while the camera's gain jumps.
        for (double t = from + rng.uniform(0.5, 1.5); t < s.seconds; t += rng.uniform(1.5, 3.0))
            s.brightness_jumps.push_back(t);
        s.brightness_jump = rng.uniform(0.2, 0.4);
        pose = [&, base = pose](double t) {
            Keyframe k = base(t);
            k.x += 0.1 * std::sin(2 * pi * t / 3 + phase);
            k.depth = d0 * (1 + 0.05 * std::sin(2 * pi * t / 4));
            return k;
        };
    } else if (motion == "pass") {
        // Ordinary slow moves while a ball the size of a head or a toy (15-40% of the frame's
        // height) crosses behind the target every 2-4 s, at about its height, in 0.8-2 s; its
        // colour dark, light, or near the target's own.
        for (double t = from + rng.uniform(0.3, 1.0); t < s.seconds; t += rng.uniform(2.0, 4.0))
            s.passes.push_back(t);
        s.pass_seconds = rng.uniform(0.8, 2.0);
        s.pass_size = rng.uniform(0.15, 0.4);
        s.pass_y = y0 + rng.uniform(-0.15, 0.15);
        const double look = rng.uniform();
        const double v = rng.uniform(0.6, 1.0);
        s.pass_colour = look < 0.35   ? Colour{40 * v, 45 * v, 50 * v}
                        : look < 0.65 ? Colour{200 * v, 205 * v, 210 * v}
                                      : default_colour(s.target, s.background);
        pose = [&, base = pose](double t) {
            Keyframe k = base(t);
            k.x += 0.06 * std::sin(2 * pi * t / 3.5 + phase);
            k.depth = d0 * (1 + 0.03 * std::sin(2 * pi * t / 4.5));
            return k;
        };
    } else if (motion == "fingers" || motion == "fist") {
        // Ordinary slow moves while the fingers close side by side (or curl into a fist) in
        // 0.2-0.5 s, stay so 0.3-1.0 s, open again as fast, and stay open 1-2 s.
        const double close = rng.uniform(0.2, 0.5);
        const double closed = rng.uniform(0.3, 1.0);
        const double open = rng.uniform(1.0, 2.0);
        const double shut = motion == "fist" ? -1.0 : 0.0;
        pose = [&, base = pose, close, closed, open, shut](double t) {
            Keyframe k = base(t);
            k.x += 0.05 * std::sin(2 * pi * t / 3.5 + phase);
            k.depth = d0 * (1 + 0.03 * std::sin(2 * pi * t / 4.5));
            int n = 0;
            const double u = cycle(t, from, 2 * close + closed + open * rate, n);
            const double in = smoothstep(u / close) - smoothstep((u - close - closed) / close);
            k.spread = 1 + (shut - 1) * in;
            return k;
        };
    }
    if (motion == "wander") {
        // The renderer's own path: wanders in x, y and depth (3.5% to 10% of the frame).
        s.speed = rng.uniform(0.8, 1.3);
    } else {
        sample_path(s, pose);
    }
    // The renderer's path comes up to 25% closer within 0.6 s at times: pushes by the targets'
    // own definition, taken out of the motion that must not click.
    clip.approaches = approaches(s, from, s.seconds, target_push_depth, target_push_seconds,
                                 approach_press_seconds);
    double start = from;
    for (const auto& [begin, end] : clip.approaches) {
        if (begin > start) clip.motion_spans.emplace_back(start, begin);
        start = end;
    }
    if (s.seconds > start) clip.motion_spans.emplace_back(start, s.seconds);
    return clip;
}

}  // namespace

std::string_view to_string(GestureKind kind) {
    switch (kind) {
        case GestureKind::click:
            return "click";
        case GestureKind::drag:
            return "drag";
        case GestureKind::right:
            return "right";
        case GestureKind::double_click:
            return "double";
        case GestureKind::scroll_up:
            return "scroll_up";
        case GestureKind::scroll_down:
            return "scroll_down";
    }
    return "?";
}

std::vector<GestureClip> gesture_set(std::string_view name, std::uint32_t seed) {
    int push_clips = 0;
    int motion_rounds = 0;
    int button_clips = 0;  // of each kind
    int pass_clips = 0;    // a second object passing behind the target
    int finger_clips = 0;  // of each: the fingers closing side by side, or into a fist
    if (name == "full") {
        push_clips = 110;
        motion_rounds = 4;  // 7 motions x 4 + 2 more = 30 clips
        button_clips = 20;
        pass_clips = 4;
        finger_clips = 4;
    } else if (name == "ci") {
        push_clips = 6;
        motion_rounds = 0;
        button_clips = 2;
    } else {
        throw std::invalid_argument("gesture set '" + std::string(name) +
                                    "': unknown (allowed: full, ci)");
    }
    const std::vector<std::string> motions = {"lean",    "walk",       "swipe", "turn",
                                              "reenter", "brightness", "wander"};
    std::vector<GestureClip> clips;
    clips.reserve(static_cast<std::size_t>(push_clips) +
                  static_cast<std::size_t>(motion_rounds) * motions.size() + 3 +
                  3 * static_cast<std::size_t>(button_clips) +
                  static_cast<std::size_t>(pass_clips) +
                  2 * static_cast<std::size_t>(finger_clips));
    for (int i = 0; i < push_clips; ++i)
        clips.push_back(push_clip(seed, i));
    int index = 0;
    for (int round = 0; round < motion_rounds; ++round) {
        for (const std::string& motion : motions)
            clips.push_back(motion_clip(seed, index++, motion, 26));
    }
    const std::vector<std::string> extra = name == "ci"
                                               ? std::vector<std::string>{"lean", "swipe", "walk"}
                                               : std::vector<std::string>{"swipe", "lean"};
    for (const std::string& motion : extra)
        clips.push_back(motion_clip(seed, index++, motion, name == "ci" ? 16 : 26));
    // After the others, so that adding them changed none of the clips above.
    for (int i = 0; i < pass_clips; ++i)
        clips.push_back(motion_clip(seed, index++, "pass", name == "ci" ? 16 : 26));
    // Their own seeds, so adding them changed none of the clips above.
    for (const GestureKind kind :
         {GestureKind::right, GestureKind::double_click, GestureKind::scroll_up}) {
        for (int i = 0; i < button_clips; ++i)
            clips.push_back(gesture::button_clip(seed, i, kind));
    }
    // After the others, so that adding them changed none of the clips above.
    for (const char* motion : {"fingers", "fist"}) {
        for (int i = 0; i < finger_clips; ++i)
            clips.push_back(motion_clip(seed, index++, motion, 26));
    }
    return clips;
}

}  // namespace raypoint::scene
