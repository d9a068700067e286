// SPDX-License-Identifier: MIT
#pragma once
// Deterministic renderer of short webcam-like clips with exact ground truth.

#include <memory>

#include <opencv2/core.hpp>

#include "raypoint/scene/presets.hpp"
#include "raypoint/scene/scene_spec.hpp"
#include "raypoint/scene/truth.hpp"

namespace raypoint::scene {

struct RenderedFrame {
    cv::Mat bgr;   // CV_8UC3, width x height
    cv::Mat mask;  // CV_8U, 255 where the target is visible at the middle of the exposure
    Truth truth;   // measured on mask
};

// Copies share the (immutable) background, sprite and noise, so copying is cheap, and
// render() may run on several threads at once.
class Renderer {
  public:
    // Throws std::invalid_argument when the spec makes no sense (sizes, rates, path).
    explicit Renderer(SceneSpec spec);

    int frame_count() const;             // round(seconds x fps)
    double frame_time(int index) const;  // index / fps: the middle of the frame's exposure
    // Any index in any order gives the same pixels for the same spec (noise is seeded by the
    // seed and the index). Throws std::out_of_range outside [0, frame_count()).
    RenderedFrame render(int index) const;
    const SceneSpec& spec() const;

    struct Assets;  // background, sprite, trajectory, noise: private to renderer.cpp

  private:
    SceneSpec spec_;
    std::shared_ptr<const Assets> assets_;
};

}  // namespace raypoint::scene
