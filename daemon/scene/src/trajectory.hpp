// SPDX-License-Identifier: MIT
#pragma once
// Where the target is at any time of the clip: the default trajectory or the spec's keyframes,
// with holds (time stands still) and pushes (depth dips) applied on top.

#include <optional>

#include "camera.hpp"
#include "raypoint/scene/scene_spec.hpp"
#include "sprite.hpp"

namespace raypoint::scene {

struct Pose {
    double x = 0;  // centre, fractions of the frame's width and height
    double y = 0;
    double depth = 0;   // m
    double angle = 0;   // rad, clockwise on screen
    double spread = 1;  // a hand's fingers, Keyframe::spread
};

class Trajectory {
  public:
    Trajectory(const SceneSpec& spec, const Camera& camera, const Sprite& sprite);

    // No pose before the target enters (t < empty_seconds).
    std::optional<Pose> at(double t) const;

  private:
    struct Wave {
        double amplitude;
        double omega;  // rad per second of path time
        double phase;
    };

    Pose default_path(double t) const;
    Pose keyframed(double t) const;
    double path_time(double t) const;  // t minus the time lost in holds
    double push_factor(double t) const;

    SceneSpec spec_;
    Camera camera_;
    cv::Rect2d extent_;  // the sprite's outline box, units
    bool rotates_;
    Wave x_waves_[2]{};
    Wave y_waves_[2]{};
    Wave depth_waves_[2]{};
    Wave angle_waves_[2]{};
    double near_depth_ = 0;  // m, the default path's depth range
    double far_depth_ = 0;
};

}  // namespace raypoint::scene
