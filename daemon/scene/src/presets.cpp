// SPDX-License-Identifier: MIT
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "raypoint/scene/presets.hpp"

namespace raypoint::scene {
namespace {

constexpr std::uint32_t rightdown_seed = 12;  // its place in `names` below, plus one
constexpr std::uint32_t realworld_seed = 5;

// A 15 cm ball on a thread, an adult hand (wrist to fingertip) or a paper one of that size.
constexpr double sphere_size_m = 0.15;
constexpr double hand_size_m = 0.19;

SceneSpec base(std::string_view name, Target target, Background background, std::uint32_t seed) {
    SceneSpec s;
    s.seed = seed;
    s.name = std::string(name);
    s.target = target;
    s.background = background;
    s.target_size_m = target == Target::sphere ? sphere_size_m : hand_size_m;
    return s;
}

// The system tests' gestures (tests/system): the paper hand on the plain board, on an explicit
// path (keyframes: t, x, y, depth).
SceneSpec gesture(std::string_view name, std::uint32_t seed, double seconds,
                  std::vector<Keyframe> path) {
    SceneSpec s = base(name, Target::hand, Background::plain, seed);
    s.seconds = seconds;
    s.noise_sigma = 2;
    s.blur = 0.4;
    s.path = std::move(path);
    return s;
}

// The hand appears at the left, stands still for the tracker to settle, moves right (0.3 -> 0.7 of
// the width), stops, moves down (0.35 -> 0.7 of the height) and stops. An explicit path, so the
// direction of every stretch is known: 4.0-5.5 s right, 7.5-9.0 s down, still in between (long
// enough to tell the two apart in a slow VM's events, which come up to a second late).
SceneSpec right_then_down(std::string_view name, std::uint32_t seed) {
    constexpr double depth = 0.65;  // m: the hand covers about 4% of the frame
    return gesture(name, seed, 11,
                   {{2.5, 0.3, 0.35, depth},
                    {4.0, 0.3, 0.35, depth},
                    {5.5, 0.7, 0.35, depth},
                    {7.5, 0.7, 0.35, depth},
                    {9.0, 0.7, 0.7, depth},
                    {11, 0.7, 0.7, depth}});
}

// A held push: the hand stands still, comes 23% closer in 0.2 s (4.0 s), stays there while it
// moves right (5.3-6.5 s, after the click's drag_seconds) and pulls back (6.8-7.0 s). Keys in
// pairs around each change keep the spline from starting it early.
SceneSpec drag(std::string_view name, std::uint32_t seed) {
    constexpr double far = 0.65;  // m
    constexpr double near = 0.5;  // m: sqrt(area) 30% up, a clear press
    return gesture(name, seed, 9,
                   {{2.5, 0.3, 0.5, far},
                    {3.8, 0.3, 0.5, far},
                    {4.0, 0.3, 0.5, far},
                    {4.2, 0.3, 0.5, near},
                    {4.4, 0.3, 0.5, near},
                    {5.3, 0.3, 0.5, near},
                    {6.5, 0.6, 0.5, near},
                    {6.8, 0.6, 0.5, near},
                    {7.0, 0.6, 0.5, far},
                    {7.2, 0.6, 0.5, far},
                    {9, 0.6, 0.5, far}});
}

// The optional click gestures (click.right_seconds, double_seconds, scroll_gain), as drag: the
// paper hand still, 23% closer in 0.2 s. rightclick: in at 5.5 s, held still 1.4 s, pulled back
// at 7.1 s. doubleclick: in at 6.0-6.25 s, back at 6.4-6.65 s and in again at 7.25-7.5 s (the
// second push begins 0.6 s after the first is out: the release comes during the pull-back and
// the refractory 0.3 s must be over, on a slow machine's sparse frames too), back at 7.65-7.9 s.
// scroll: in at 5.5 s, held while moving up (0.6 -> 0.35 of the height, 5.8-7.3 s: moving at once,
// or holding still would right-click), pulled back at 7.6 s. Pushes from 5.5 s leave a slow VM's
// daemon time to be tracking for min_tracking_seconds.
SceneSpec button_gesture(std::string_view name, std::uint32_t seed) {
    constexpr double far = 0.65;
    constexpr double near = 0.5;
    if (name == "rightclick") {
        return gesture(name, seed, 10.5,
                       {{2.5, 0.5, 0.5, far},
                        {5.3, 0.5, 0.5, far},
                        {5.5, 0.5, 0.5, far},
                        {5.7, 0.5, 0.5, near},
                        {5.9, 0.5, 0.5, near},
                        {6.9, 0.5, 0.5, near},
                        {7.1, 0.5, 0.5, near},
                        {7.3, 0.5, 0.5, far},
                        {7.5, 0.5, 0.5, far},
                        {10.5, 0.5, 0.5, far}});
    }
    if (name == "doubleclick") {
        return gesture(name, seed, 10,
                       {{2.5, 0.5, 0.5, far},
                        {5.8, 0.5, 0.5, far},
                        {6.0, 0.5, 0.5, far},
                        {6.25, 0.5, 0.5, near},
                        {6.4, 0.5, 0.5, near},
                        {6.65, 0.5, 0.5, far},
                        {7.25, 0.5, 0.5, far},
                        {7.5, 0.5, 0.5, near},
                        {7.65, 0.5, 0.5, near},
                        {7.9, 0.5, 0.5, far},
                        {8.1, 0.5, 0.5, far},
                        {10, 0.5, 0.5, far}});
    }
    return gesture(name, seed, 11,
                   {{2.5, 0.5, 0.6, far},
                    {5.3, 0.5, 0.6, far},
                    {5.5, 0.5, 0.6, far},
                    {5.7, 0.5, 0.6, near},
                    {5.8, 0.5, 0.6, near},
                    {7.3, 0.5, 0.35, near},
                    {7.6, 0.5, 0.35, near},
                    {7.8, 0.5, 0.35, far},
                    {8.0, 0.5, 0.35, far},
                    {11, 0.5, 0.35, far}});
}

// A skin hand where something near its colour is behind or beside it, as realworld's camera
// sees it (noise 3, half-frame blur, 0.9 x speed).
SceneSpec skin_lookalike(std::string_view name, std::uint32_t seed) {
    SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
    s.noise_sigma = 3;
    s.blur = 0.5;
    s.speed = 0.9;
    if (name == "person") {
        // The user behind their own hand: face and neck of the hand's skin, breathing and
        // turning the head, in front of a room.
        s.person = true;
    } else if (name == "skinwall") {
        s.background = Background::skin_wall;
    } else if (name == "desk") {
        s.background = Background::desk;
    } else if (name == "sleeve") {
        // A beige knit sleeve: 12-24 grey levels from the skin in each channel, about the edge
        // threshold's step.
        s.sleeve_colour = Colour{112, 146, 190};
    } else {
        return {};
    }
    return s;
}

SceneSpec make(std::string_view name, std::uint32_t seed) {
    if (name == "ideal") return base(name, Target::sphere, Background::plain, seed);
    if (name == "lowlight") {
        SceneSpec s = base(name, Target::sphere, Background::plain, seed);
        s.fps = 10;  // the paper's low-budget cameras dropped to 10 fps in low light
        s.darkness = 0.42;
        s.noise_sigma = 8;
        s.blur = 0.9;
        return s;
    }
    if (name == "interfering") {
        SceneSpec s = base(name, Target::sphere, Background::cluttered, seed);
        s.noise_sigma = 2.5;
        s.blur = 0.4;
        return s;
    }
    if (name == "nonconvex") {
        SceneSpec s = base(name, Target::hand, Background::plain, seed);
        s.noise_sigma = 2;
        s.blur = 0.4;
        s.speed = 0.9;
        return s;
    }
    if (name == "realworld") {
        SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
        s.noise_sigma = 3;
        s.blur = 0.5;
        s.speed = 0.9;
        return s;
    }
    if (name == "hd60") {
        SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
        s.fps = 60;
        return s;
    }
    if (name == "exposure") {
        SceneSpec s = base(name, Target::sphere, Background::plain, seed);
        s.noise_sigma = 2;
        s.blur = 0.4;
        // Two jumps in the empty scene (the tracker's start-up), four while tracking.
        s.brightness_jumps = {0.7, 1.6, 3.2, 3.9, 4.6, 5.4};
        return s;
    }
    if (name == "jpeg") {
        SceneSpec s = base(name, Target::sphere, Background::cluttered, seed);
        s.noise_sigma = 2;
        s.blur = 0.4;
        s.jpeg_quality = 35;
        return s;
    }
    if (name == "fast") {
        SceneSpec s = base(name, Target::hand, Background::plain, seed);
        s.fps = 15;
        s.seconds = 8;
        s.speed = 2.4;
        s.blur = 1.0;
        s.noise_sigma = 3;
        return s;
    }
    if (name == "pause") {
        SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
        s.seconds = 10;
        s.noise_sigma = 2.5;
        s.blur = 0.4;
        s.holds = {{4.5, 3.5}};
        return s;
    }
    if (name == "push") {
        SceneSpec s = base(name, Target::hand, Background::plain, seed);
        s.seconds = 9;
        s.noise_sigma = 2;
        s.blur = 0.4;
        // Comes to rest, clicks twice by pushing toward the camera, moves on.
        s.holds = {{4.5, 3.3}};
        s.pushes = {5.0, 6.6};
        return s;
    }
    if (name == "rightdown") return right_then_down(name, seed);
    if (name == "click") {
        // rightdown's motion and board (its seed) with one push in the stop between the moves.
        SceneSpec s = right_then_down(name, rightdown_seed);
        s.pushes = {6.0};
        return s;
    }
    if (name == "drag") return drag(name, seed);
    if (name == "rightclick" || name == "doubleclick" || name == "scroll")
        return button_gesture(name, seed);
    if (name == "flicker") {
        // A skin hand in a room lit by fluorescent tubes on 50 Hz mains, through a cheap webcam's
        // MJPEG (quality 60): 12% bands rolling through every frame.
        SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
        s.noise_sigma = 3;
        s.blur = 0.5;
        s.flicker_depth = 0.12;
        s.jpeg_quality = 60;
        return s;
    }
    if (name == "drift") {
        // Auto-exposure and white balance hunting the whole clip (+-20% gain, +-10% per channel,
        // a 3 s period), as a webcam does under mixed daylight and lamp light.
        SceneSpec s = base(name, Target::hand, Background::cluttered, seed);
        s.noise_sigma = 3;
        s.blur = 0.5;
        s.exposure_drift = 0.2;
        s.white_balance_drift = 0.1;
        s.drift_period = 3.0;
        return s;
    }
    if (name == "passer") {
        // realworld's room, hand and path (its seed) while a dark ball the size of a head (a
        // quarter of the frame's height) crosses behind the hand every 2.5 s, at about its
        // height, in 1.2 s: a second moving object the tracker must not take. Only the ball
        // differs from realworld.
        SceneSpec s = make("realworld", realworld_seed);
        s.name = std::string(name);
        s.passes = {3.5, 6.0, 8.5};
        s.seconds = 10;
        s.pass_seconds = 1.2;
        s.pass_size = 0.25;
        s.pass_y = 0.5;
        return s;
    }
    if (name == "skew") {
        // realworld's room and path (its seed) at twice its speed, through a cheap webcam's
        // rolling shutter: rows read over 30 ms of the 33 ms frame, up to ~10 px of shear at
        // 640x480. Only the shutter and the speed differ from realworld.
        SceneSpec s = make("realworld", realworld_seed);
        s.name = std::string(name);
        s.blur = 0.3;
        s.speed = 1.8;
        s.rolling_shutter = true;
        s.readout_seconds = 0.030;
        return s;
    }
    return skin_lookalike(name, seed);
}

constexpr std::array<std::string_view, 25> names{
    "ideal",    "lowlight", "interfering", "nonconvex",   "realworld", "hd60",  "exposure",
    "jpeg",     "fast",     "pause",       "push",        "rightdown", "click", "drag",
    "flicker",  "drift",    "rightclick",  "doubleclick", "scroll",    "skew",  "person",
    "skinwall", "desk",     "sleeve",      "passer"};

}  // namespace

SceneSpec preset(std::string_view name) {
    // Each preset gets its own seed: its own room and trajectory.
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return make(name, static_cast<std::uint32_t>(i + 1));
    }
    std::string valid;
    for (const std::string_view known : names) {
        valid += valid.empty() ? "" : ", ";
        valid += known;
    }
    throw std::invalid_argument("unknown scene preset \"" + std::string(name) +
                                "\"; valid presets: " + valid);
}

std::vector<std::string_view> preset_names() {
    return {names.begin(), names.end()};
}

}  // namespace raypoint::scene
