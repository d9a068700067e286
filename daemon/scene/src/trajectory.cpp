// SPDX-License-Identifier: MIT
#include "trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rng.hpp"

namespace raypoint::scene {
namespace {

constexpr double entry_seconds = 0.6;  // from just outside the right edge onto the path
constexpr double hold_ramp = 0.25;     // s of slowing down before / speeding up after a hold
constexpr double push_dwell = 0.1;     // s at the deepest point of a push
// The default path's depth range, as the share of the frame the target covers.
constexpr double far_area = 0.035;
constexpr double near_area = 0.10;
constexpr double max_wobble = 0.22;  // rad, the default path's largest in-plane rotation
constexpr double edge_margin = 0.02;

double smoothstep(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

// Half the width and height (units) of the box around `extent` rotated by `angle`; the
// extent is centred on the target's centre.
cv::Point2d rotated_half_size(const cv::Rect2d& extent, double angle) {
    const double c = std::abs(std::cos(angle));
    const double s = std::abs(std::sin(angle));
    const double hw = extent.width / 2;
    const double hh = extent.height / 2;
    return {hw * c + hh * s, hw * s + hh * c};
}

// Time lost to a hold by time t: the integral of (1 - speed), where speed eases from 1 to 0
// over the ramp before the hold and back over the ramp after it.
double time_lost(const Hold& hold, double t) {
    const double r = hold_ramp;
    const double pi = std::numbers::pi;
    const double down = hold.start - r;
    const double end = hold.start + hold.seconds;
    if (t <= down) return 0;
    if (t <= hold.start) {
        const double u = t - down;
        return u / 2 - r / (2 * pi) * std::sin(pi * u / r);
    }
    if (t <= end) return r / 2 + (t - hold.start);
    const double u = std::min(t - end, r);
    return r / 2 + hold.seconds + u / 2 + r / (2 * pi) * std::sin(pi * u / r);
}

// Cubic Hermite through (t_k, v_k) with finite-difference slopes, flat at both ends.
double hermite(const std::vector<Keyframe>& keys, double t, double Keyframe::*field) {
    if (t <= keys.front().t) return keys.front().*field;
    if (t >= keys.back().t) return keys.back().*field;
    const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                       [](double v, const Keyframe& k) { return v < k.t; });
    const std::size_t i = static_cast<std::size_t>(next - keys.begin()) - 1;
    auto slope = [&](std::size_t k) {
        if (k == 0 || k + 1 >= keys.size()) return 0.0;
        return (keys[k + 1].*field - keys[k - 1].*field) / (keys[k + 1].t - keys[k - 1].t);
    };
    const double h = keys[i + 1].t - keys[i].t;
    const double u = (t - keys[i].t) / h;
    const double u2 = u * u;
    const double u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * (keys[i].*field) + (u3 - 2 * u2 + u) * h * slope(i) +
           (-2 * u3 + 3 * u2) * (keys[i + 1].*field) + (u3 - u2) * h * slope(i + 1);
}

}  // namespace

Trajectory::Trajectory(const SceneSpec& spec, const Camera& camera, const Sprite& sprite)
    : spec_(spec), camera_(camera), extent_(sprite.extent), rotates_(sprite.rotates) {
    const double frame_px = static_cast<double>(camera.width) * camera.height;
    auto depth_for_area = [&](double area) {
        return camera.focal_px() * spec.target_size_m * std::sqrt(sprite.area / (area * frame_px));
    };
    near_depth_ = depth_for_area(near_area);
    far_depth_ = depth_for_area(far_area);
    // The target must fit in the frame at its nearest, whatever the frame's aspect.
    const cv::Point2d half = rotated_half_size(extent_, rotates_ ? max_wobble : 0);
    const double fit = std::max(2 * half.x * spec.target_size_m * camera.focal_px() /
                                    (camera.width * (1 - 4 * edge_margin)),
                                2 * half.y * spec.target_size_m * camera.focal_px() /
                                    (camera.height * (1 - 4 * edge_margin)));
    near_depth_ = std::max(near_depth_, fit);
    far_depth_ = std::max(far_depth_, near_depth_ * 1.2);
    const double scale = camera.focal_px() * spec.target_size_m / near_depth_;
    const double amp_x = std::max(0.0, 0.5 - half.x * scale / camera.width - edge_margin);
    const double amp_y = std::max(0.0, 0.5 - half.y * scale / camera.height - edge_margin);

    Rng rng(mix_seed(spec.seed, 2));
    const double two_pi = 2 * std::numbers::pi;
    // Sums of two sines with unrelated frequencies never quite repeat; the first x phase
    // starts the path on the right half, where the target comes in.
    x_waves_[0] = {0.72 * amp_x, 1.05, rng.uniform(0.5, 1.5)};
    x_waves_[1] = {0.28 * amp_x, 2.3, rng.uniform(0, two_pi)};
    y_waves_[0] = {0.7 * amp_y, 1.37, rng.uniform(0, two_pi)};
    y_waves_[1] = {0.3 * amp_y, 2.9, rng.uniform(0, two_pi)};
    depth_waves_[0] = {0.75, 1.45, rng.uniform(0, two_pi)};
    depth_waves_[1] = {0.25, 2.6, rng.uniform(0, two_pi)};
    angle_waves_[0] = {0.16, 0.7, rng.uniform(0, two_pi)};
    angle_waves_[1] = {0.06, 1.9, rng.uniform(0, two_pi)};
}

double Trajectory::path_time(double t) const {
    double lost = 0;
    for (const Hold& h : spec_.holds)
        lost += time_lost(h, t);
    return t - lost;
}

namespace {

// How far into a push (0..1) its depth is at u seconds from its start: eased in over p, held
// for `hold`, eased out over p.
double push_share(double u, double p, double hold) {
    if (u <= 0 || u >= 2 * p + hold) return 0;
    if (u < p) return smoothstep(u / p);
    if (u < p + hold) return 1;
    return 1 - smoothstep((u - p - hold) / p);
}

}  // namespace

double Trajectory::push_factor(double t) const {
    double factor = 1;
    for (const double start : spec_.pushes)
        factor *= 1 - spec_.push_depth * push_share(t - start, spec_.push_seconds, push_dwell);
    for (const SceneSpec::Push& push : spec_.shaped_pushes)
        factor *= 1 - push.depth * push_share(t - push.start, push.seconds, push.hold);
    return factor;
}

Pose Trajectory::default_path(double t) const {
    const double tau = spec_.speed * (path_time(t) - path_time(spec_.empty_seconds));
    auto sum = [tau](const Wave(&waves)[2]) {
        return waves[0].amplitude * std::sin(waves[0].omega * tau + waves[0].phase) +
               waves[1].amplitude * std::sin(waves[1].omega * tau + waves[1].phase);
    };
    Pose pose;
    pose.x = 0.5 + sum(x_waves_);
    pose.y = 0.5 + sum(y_waves_);
    // Even steps in 1 / depth, so that the area (~ 1 / depth^2) is spread evenly.
    const double w = 0.5 + 0.5 * sum(depth_waves_);
    pose.depth = 1 / (1 / far_depth_ + (1 / near_depth_ - 1 / far_depth_) * w);
    pose.angle = rotates_ ? sum(angle_waves_) : 0;
    // Entry: slide in from just beyond the right edge, easing into the path.
    const double u = (t - spec_.empty_seconds) / entry_seconds;
    if (u < 1) {
        const double scale = camera_.focal_px() * spec_.target_size_m / pose.depth;
        const double outside =
            1 + rotated_half_size(extent_, pose.angle).x * scale / camera_.width + 0.002;
        const double e = smoothstep(u);
        pose.x = outside + (pose.x - outside) * e;
    }
    return pose;
}

Pose Trajectory::keyframed(double t) const {
    const double w = path_time(t);
    const std::vector<Keyframe>& keys = spec_.path;
    Pose pose;
    pose.x = hermite(keys, w, &Keyframe::x);
    pose.y = hermite(keys, w, &Keyframe::y);
    pose.depth = std::max(hermite(keys, w, &Keyframe::depth), 1e-3);
    pose.angle = rotates_ ? hermite(keys, w, &Keyframe::angle) : 0;
    pose.spread = std::clamp(hermite(keys, w, &Keyframe::spread), -1.0, 1.0);
    return pose;
}

std::optional<Pose> Trajectory::at(double t) const {
    if (t < spec_.empty_seconds) return std::nullopt;
    Pose pose = spec_.path.empty() ? default_path(t) : keyframed(t);
    pose.depth *= push_factor(t);
    return pose;
}

}  // namespace raypoint::scene
