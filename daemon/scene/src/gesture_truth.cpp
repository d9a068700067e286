// SPDX-License-Identifier: MIT
// What the gesture set's clips carry beside their pictures: the truth file, and the same clips
// in front of photographs.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "raypoint/scene/gesture_set.hpp"
#include "rng.hpp"

namespace raypoint::scene {

void use_photos(std::vector<GestureClip>& clips, const std::vector<std::string>& photos,
                std::uint32_t seed) {
    if (photos.empty()) throw std::invalid_argument("use_photos: no photographs");
    for (std::size_t i = 0; i < clips.size(); ++i) {
        SceneSpec& s = clips[i].spec;
        Rng rng(mix_seed(seed, 9000 + static_cast<std::uint64_t>(i)));
        s.background = Background::photo;
        s.background_photo = photos[rng.next() % photos.size()];
        for (auto& [condition, value] : clips[i].conditions) {
            if (condition == "background") value = "photo";
        }
    }
}

std::string click_truth_text(const GestureClip& clip) {
    std::string text = "# " + clip.spec.name + ": kind start press release depth seconds\n";
    char line[160];
    for (const IntendedClick& c : clip.clicks) {
        std::snprintf(line, sizeof line, "%s %.3f %.3f %.3f %.3f %.3f\n",
                      std::string(to_string(c.kind)).c_str(), c.start, c.press, c.release, c.depth,
                      c.seconds);
        text += line;
    }
    for (const auto& [from, to] : clip.motion_spans) {
        std::snprintf(line, sizeof line, "motion %.3f %.3f\n", from, to);
        text += line;
    }
    for (const auto& [from, to] : clip.approaches) {
        std::snprintf(line, sizeof line, "approach %.3f %.3f\n", from, to);
        text += line;
    }
    return text;
}

}  // namespace raypoint::scene
