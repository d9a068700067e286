// SPDX-License-Identifier: MIT
#include "raypoint/scene/approaches.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "camera.hpp"
#include "sprite.hpp"
#include "trajectory.hpp"

namespace raypoint::scene {

std::vector<std::pair<double, double>> approaches(const SceneSpec& spec, double from, double to,
                                                  double closer, double within, double after) {
    const Camera camera{spec.width, spec.height};
    const auto sprite = shared_sprite(
        spec.target, spec.target_colour.value_or(default_colour(spec.target, spec.background)));
    const Trajectory trajectory(spec, camera, *sprite);
    std::vector<double> times;
    std::vector<double> depths;  // m; NaN without a target
    const int frames = static_cast<int>(std::lround(spec.seconds * spec.fps));
    for (int i = 0; i < frames; ++i) {
        const double t = i / spec.fps;
        if (t < from - within || t > to) continue;
        const std::optional<Pose> pose = trajectory.at(t);
        times.push_back(t);
        depths.push_back(pose ? pose->depth : std::nan(""));
    }
    std::vector<std::pair<double, double>> spans;
    std::size_t first = 0;  // the earliest frame within `within` of frame j
    for (std::size_t j = 0; j < times.size(); ++j) {
        while (times[j] - times[first] > within + 1e-9)
            ++first;
        // The latest frame that far back: the shortest such approach ending at frame j, which
        // starts where the target set off, not up to `within` before it.
        for (std::size_t i = j; i-- > first;) {
            // NaN compares false: no approach across a frame without the target.
            if (!(depths[j] <= (1.0 - closer) * depths[i])) continue;
            const double begin = std::max(from, times[i]);
            const double end = std::min(to, times[j] + after);
            if (end <= begin) break;
            if (!spans.empty() && begin <= spans.back().second) {
                spans.back().first = std::min(spans.back().first, begin);
                spans.back().second = std::max(spans.back().second, end);
            } else {
                spans.emplace_back(begin, end);
            }
            break;
        }
    }
    return spans;
}

}  // namespace raypoint::scene
