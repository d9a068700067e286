// SPDX-License-Identifier: MIT
#include "bench_clip.hpp"

#include <filesystem>
#include <stdexcept>

#include "input_error.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {
namespace {

namespace fs = std::filesystem;

// "scenes/ideal/video.mp4" is the clip "ideal"; "hand.mp4" is "hand".
std::string clip_name(const fs::path& video) {
    if (video.filename() == "video.mp4" && video.has_parent_path()) {
        const fs::path folder = fs::absolute(video).parent_path();
        if (!folder.filename().empty()) return folder.filename().string();
    }
    return video.stem().string();
}

// The video of a CLIP argument: the file itself, or a scene folder's video.mp4.
fs::path video_path(const std::string& argument) {
    fs::path video(argument);
    std::error_code error;
    if (fs::is_directory(video, error)) {
        video /= "video.mp4";
        if (!fs::exists(video, error)) {
            throw InputError(argument + ": is a directory without video.mp4 (expected a video " +
                             "file or a scene folder)");
        }
    }
    return video;
}

fs::path truth_folder(const fs::path& video) {
    return video.has_parent_path() ? video.parent_path() : fs::path(".");
}

}  // namespace

void check_clip(const std::string& argument) {
    const fs::path video = video_path(argument);
    const VideoSource source(video.string(), 0.0);
    read_ground_truth(truth_folder(video), 2);
}

BenchClip load_clip(const std::string& argument, int max_frames) {
    const fs::path video = video_path(argument);
    BenchClip clip;
    clip.name = clip_name(video);
    VideoSource source(video.string(), 0.0);
    while (max_frames <= 0 || static_cast<int>(clip.frames.size()) < max_frames) {
        auto frame = source.next();
        if (!frame) break;
        clip.frames.push_back(std::move(*frame));
    }
    clip.truth = read_ground_truth(truth_folder(video), max_frames);
    return clip;
}

BenchClip render_clip(const std::string& preset, int max_frames) {
    scene::SceneSpec spec;
    try {
        spec = scene::preset(preset);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--scenes: ") + e.what());
    }
    const scene::Renderer renderer(spec);
    BenchClip clip;
    clip.name = spec.name;
    clip.truth.emplace();
    int count = renderer.frame_count();
    if (max_frames > 0) count = std::min(count, max_frames);
    for (int index = 0; index < count; ++index) {
        scene::RenderedFrame rendered = renderer.render(index);
        clip.frames.push_back({rendered.bgr, core::seconds_to_us(renderer.frame_time(index))});
        clip.truth->truth.push_back(rendered.truth);
        clip.truth->masks.push_back(rendered.mask);
    }
    return clip;
}

}  // namespace raypoint::daemon
