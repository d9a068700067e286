// SPDX-License-Identifier: MIT
#include "raypoint/scene/json.hpp"

#include <cstdio>
#include <string>

namespace raypoint::scene {
namespace {

// Like Python's repr(round(v, decimals)), which the dev scenes were written with:
// "2.5", "0.0", "0.033333".
std::string number(double v, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    std::string s(buffer);
    while (s.size() > 1 && s.back() == '0' && s[s.size() - 2] != '.')
        s.pop_back();
    if (s == "-0.0") s = "0.0";
    return s;
}

std::string list(const std::vector<double>& values, int decimals) {
    std::string s = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        s += (i ? ", " : "") + number(values[i], decimals);
    }
    return s + "]";
}

std::string quoted(const std::string& text) {
    std::string s = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') s += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        s += c;
    }
    return s + "\"";
}

}  // namespace

std::string truth_json(const Truth& truth) {
    std::string s = "{\"frame\": " + std::to_string(truth.frame) +
                    ", \"t\": " + number(truth.t, 6) +
                    ", \"present\": " + (truth.present ? "true" : "false");
    if (truth.present) {
        s += std::string(", \"moving\": ") + (truth.moving ? "true" : "false");
        s += ", \"centroid\": " + list({truth.cx, truth.cy}, 6);
        s += ", \"area\": " + number(truth.area, 6);
        s += ", \"bbox\": " + list({truth.bx, truth.by, truth.bw, truth.bh}, 5);
        s += ", \"depth\": " + number(truth.depth, 5);
    }
    return s + "}";
}

namespace {

const char* background_name(Background background) {
    switch (background) {
        case Background::plain:
            return "white";
        case Background::cluttered:
            return "clutter";
        case Background::skin_wall:
            return "skin_wall";
        case Background::desk:
            return "desk";
        case Background::photo:
            return "photo";
    }
    return "white";
}

}  // namespace

std::string scene_json(const SceneSpec& spec, int frames) {
    std::vector<double> hold_starts;
    std::vector<double> hold_seconds;
    for (const Hold& h : spec.holds) {
        hold_starts.push_back(h.start);
        hold_seconds.push_back(h.seconds);
    }
    std::string s = "{\n";
    auto field = [&s](const std::string& key, const std::string& value) {
        s += (s.size() > 2 ? ",\n" : "") + std::string(" ") + quoted(key) + ": " + value;
    };
    field("name", quoted(spec.name));
    field("width", std::to_string(spec.width));
    field("height", std::to_string(spec.height));
    field("frames", std::to_string(frames));
    field("bg", quoted(background_name(spec.background)));
    field("sleeve", spec.sleeve_colour ? "true" : "false");
    field("person", spec.person ? "true" : "false");
    field("passes", std::to_string(spec.passes.size()));
    field("obj", quoted(spec.target == Target::sphere ? "sphere" : "hand"));
    field("fps", number(spec.fps, 6));
    field("noise", number(spec.noise_sigma, 6));
    field("blur", number(spec.blur, 6));
    field("speed", number(spec.speed, 6));
    field("gain", number(spec.darkness, 6));
    field("jpeg", std::to_string(spec.jpeg_quality));
    field("jumps", std::to_string(spec.brightness_jumps.size()));
    field("jump_times", list(spec.brightness_jumps, 6));
    field("jump_gain", number(spec.brightness_jump, 6));
    field("seconds", number(spec.seconds, 6));
    field("empty_seconds", number(spec.empty_seconds, 6));
    field("hold_starts", list(hold_starts, 6));
    field("hold_seconds", list(hold_seconds, 6));
    field("pushes", list(spec.pushes, 6));
    field("push_depth", number(spec.push_depth, 6));
    field("push_seconds", number(spec.push_seconds, 6));
    field("keyframes", std::to_string(spec.path.size()));
    field("target_size_m", number(spec.target_size_m, 6));
    field("seed", std::to_string(spec.seed));
    return s + "\n}\n";
}

}  // namespace raypoint::scene
