#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "raypoint/scene/presets.hpp"

namespace raypoint::scene {
namespace {

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
    return {};
}

constexpr std::array<std::string_view, 11> names{
    "ideal",    "lowlight", "interfering", "nonconvex", "realworld", "hd60",
    "exposure", "jpeg",     "fast",        "pause",     "push"};

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
