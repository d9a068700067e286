// SPDX-License-Identifier: MIT
#include "raypoint/view/track_log.hpp"

#include <array>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace raypoint::view {
namespace {

constexpr std::array<core::TrackerState, 5> all_states{
    core::TrackerState::initializing, core::TrackerState::searching, core::TrackerState::tracking,
    core::TrackerState::validating, core::TrackerState::recovering};

// The text after `"key":` in a JSONL line, or nothing when the key is absent.
std::optional<std::string_view> field(std::string_view line, std::string_view key) {
    const std::string pattern = std::string("\"").append(key).append("\":");
    const std::size_t at = line.find(pattern);
    if (at == std::string_view::npos) return std::nullopt;
    return line.substr(at + pattern.size());
}

// Reads a number at the start of `text` and moves past it; false when there is none.
bool read_number(std::string_view& text, double& value) {
    const std::string copy(text.substr(0, std::min<std::size_t>(text.size(), 40)));
    char* end = nullptr;
    value = std::strtod(copy.c_str(), &end);
    if (end == copy.c_str()) return false;
    text.remove_prefix(static_cast<std::size_t>(end - copy.c_str()));
    return true;
}

std::ifstream open_or_throw(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw TrackLogError(path.string() + ": cannot open (check the path)");
    return in;
}

}  // namespace

TrackLog read_track_jsonl(const std::filesystem::path& path) {
    std::ifstream in = open_or_throw(path);
    TrackLog log;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty()) continue;
        const auto fail = [&](const std::string& reason) {
            return TrackLogError(path.string() + ":" + std::to_string(number) + ": " + reason);
        };
        TrackSample sample;
        auto t = field(line, "t");
        if (!t || !read_number(*t, sample.t)) throw fail("no \"t\" (not raypoint track's JSONL)");
        const auto state = field(line, "state");
        bool known = false;
        for (const core::TrackerState s : all_states) {
            if (state &&
                state->starts_with(std::string("\"").append(core::to_string(s)).append("\""))) {
                sample.state = s;
                known = true;
            }
        }
        if (!known) throw fail("no known \"state\"");
        if (auto position = field(line, "position"); position && position->starts_with("[")) {
            position->remove_prefix(1);
            double x = 0, y = 0, z = 0;
            const bool ok = read_number(*position, x) && position->starts_with(",") &&
                            (position->remove_prefix(1), read_number(*position, y)) &&
                            position->starts_with(",") &&
                            (position->remove_prefix(1), read_number(*position, z));
            if (!ok) throw fail("\"position\" is not [x,y,z]");
            sample.has_position = true;
            sample.position = {x, y, z};
        }
        if (const auto click = field(line, "click")) {
            if (click->starts_with("\"press\"")) log.clicks.push_back({sample.t, true});
            if (click->starts_with("\"release\"")) log.clicks.push_back({sample.t, false});
        }
        log.samples.push_back(sample);
    }
    if (log.samples.empty()) throw TrackLogError(path.string() + ": no frames");
    return log;
}

std::vector<ClickMark> read_sink_clicks(const std::filesystem::path& path) {
    std::ifstream in = open_or_throw(path);
    std::vector<ClickMark> clicks;
    std::string line;
    while (std::getline(in, line)) {
        long long us = 0;
        char type[32] = {};
        char code[32] = {};
        int value = 0;
        if (std::sscanf(line.c_str(), "%lld %31s %31s %d", &us, type, code, &value) != 4) continue;
        if (std::string_view(type) != "EV_KEY" || std::string_view(code) != "BTN_LEFT") continue;
        clicks.push_back({static_cast<double>(us) * 1e-6, value != 0});
    }
    return clicks;
}

}  // namespace raypoint::view
