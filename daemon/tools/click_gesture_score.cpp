// SPDX-License-Identifier: MIT
#include "click_gesture_score.hpp"

#include <algorithm>

namespace raypoint::daemon {

bool any_in(const std::vector<double>& times, double from, double to) {
    return std::any_of(times.begin(), times.end(), [&](double t) { return t >= from && t <= to; });
}

std::pair<int, std::optional<double>> wheel_in(const Outputs& out, double from, double to) {
    int sum = 0;
    std::optional<double> first;
    for (const auto& [t, units] : out.wheel) {
        if (t < from || t > to) continue;
        sum += units;
        if (!first) first = t;
    }
    return {sum, first};
}

GestureScore score_gesture(const scene::IntendedClick& g, const std::vector<Press>& presses,
                           std::vector<bool>& used, const Outputs& out) {
    // `used` marks them so that no left click's precision counts them.
    const double to = g.release + match_slack;
    GestureScore score;
    bool left = false;
    for (std::size_t i = 0; i < presses.size(); ++i) {
        if (used[i] || presses[i].at < g.start || presses[i].at > to) continue;
        used[i] = true;
        left = true;
        if (g.kind == scene::GestureKind::double_click && presses[i].doubled && !score.found) {
            score.found = true;
            score.at = presses[i].at;
        }
    }
    const bool right = any_in(out.rights, g.start, to);
    const auto [wheel, first_wheel] = wheel_in(out, g.start, to);
    switch (g.kind) {
        case scene::GestureKind::right:
            score.found = right;
            for (double t : out.rights) {
                if (t >= g.start && t <= to && !score.at) score.at = t;
            }
            break;
        case scene::GestureKind::scroll_up:
        case scene::GestureKind::scroll_down:
            score.found = !left && !right &&
                          (g.kind == scene::GestureKind::scroll_up ? wheel > 0 : wheel < 0);
            score.at = first_wheel;
            break;
        case scene::GestureKind::double_click:
        case scene::GestureKind::click:
        case scene::GestureKind::drag:
            break;
    }
    score.as_left = left && !score.found;
    return score;
}

GestureTally& gesture_tally(Tally& tally, scene::GestureKind kind) {
    switch (kind) {
        case scene::GestureKind::right:
            return tally.right;
        case scene::GestureKind::double_click:
            return tally.double_click;
        case scene::GestureKind::scroll_up:
        case scene::GestureKind::scroll_down:
        case scene::GestureKind::click:
        case scene::GestureKind::drag:
            break;
    }
    return tally.scroll;
}

}  // namespace raypoint::daemon
