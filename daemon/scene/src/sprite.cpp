// SPDX-License-Identifier: MIT
#include "sprite.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <tuple>

namespace raypoint::scene {
namespace {

// Fine enough that a target filling the frame's height at 640x480 is not magnified much.
constexpr double texels_per_unit = 320;
constexpr double margin_units = 0.06;  // texture beyond the outline, for anti-aliasing

double smoothstep(double edge0, double edge1, double x) {
    const double u = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

struct Capsule {
    cv::Point2d a;
    cv::Point2d b;
    double radius;

    double distance(cv::Point2d p) const {
        const cv::Point2d pa = p - a;
        const cv::Point2d ba = b - a;
        const double h = std::clamp(pa.dot(ba) / ba.dot(ba), 0.0, 1.0);
        return cv::norm(pa - ba * h) - radius;
    }
};

struct Ellipse {
    cv::Point2d centre;
    double rx;
    double ry;

    // Quilez's approximation: exact zero set, close to the true distance near the outline,
    // which is all that anti-aliasing needs.
    double distance(cv::Point2d p) const {
        const cv::Point2d q = p - centre;
        const double k0 = std::hypot(q.x / rx, q.y / ry);
        const double k1 = std::hypot(q.x / (rx * rx), q.y / (ry * ry));
        return k1 > 0 ? k0 * (k0 - 1) / k1 : -std::min(rx, ry);
    }
};

// A flat right hand, palm to the camera, fingers fanned over 70 degrees and the thumb out to
// the side (spread 1), fingers side by side and the thumb along the index (spread 0), curled
// into a fist (spread -1: fingers shortened to their knuckles, the thumb folded across the
// palm), and anything between; drawn in raw units (palm 0.44 wide), normalised to the fanned
// hand's height afterwards.
struct HandShape {
    Ellipse palm{{0, 0.10}, 0.22, 0.25};
    Capsule wrist{{0, 0.25}, {0, 0.36}, 0.13};
    std::array<Capsule, 5> fingers{};

    explicit HandShape(double spread = 1.0) {
        struct Finger {
            double x, y, fanned, together, length, radius;
        };
        // Base inside the palm, direction from straight up (clockwise positive) fanned and
        // together, length to the tip's centre. Widths ~ 1/6 of the hand's height, as on a
        // real hand; together, neighbouring fingers touch.
        constexpr std::array<Finger, 5> spec{{
            {0.17, 0.14, 1.25, 0.55, 0.34, 0.088},       // thumb
            {0.12, -0.05, 0.46, 0.12, 0.50, 0.086},      // index
            {0.03, -0.10, 0.06, 0.03, 0.54, 0.088},      // middle
            {-0.075, -0.08, -0.34, -0.06, 0.50, 0.084},  // ring
            {-0.16, -0.01, -0.76, -0.17, 0.40, 0.076},   // little
        }};
        // A fist: the fingers' last two joints folded behind the palm leave a quarter of their
        // length, the thumb lies across the palm's lower half.
        constexpr double fist_length = 0.25;
        constexpr double fist_thumb_angle = -1.2;
        constexpr double fist_thumb_length = 0.28;
        spread = std::clamp(spread, -1.0, 1.0);
        const double open = std::max(spread, 0.0);
        const double curl = std::max(-spread, 0.0);
        for (std::size_t i = 0; i < spec.size(); ++i) {
            const Finger& f = spec[i];
            double angle = f.fanned + (f.together - f.fanned) * (1.0 - open);  // exact at 1
            double length = f.length * (1.0 - (1.0 - fist_length) * curl);
            if (i == 0) {
                angle += (fist_thumb_angle - f.together) * curl;
                length = f.length + (fist_thumb_length - f.length) * curl;
            }
            const cv::Point2d base(f.x, f.y);
            const cv::Point2d dir(std::sin(angle), -std::cos(angle));
            fingers[i] = Capsule{base, base + dir * length, f.radius};
        }
    }

    double distance(cv::Point2d p) const {
        double d = std::min(palm.distance(p), wrist.distance(p));
        for (const Capsule& c : fingers)
            d = std::min(d, c.distance(p));
        return d;
    }

    cv::Rect2d bounds() const {
        double x0 = palm.centre.x - palm.rx, x1 = palm.centre.x + palm.rx;
        double y0 = palm.centre.y - palm.ry, y1 = palm.centre.y + palm.ry;
        auto add = [&](const Capsule& c) {
            x0 = std::min({x0, c.a.x - c.radius, c.b.x - c.radius});
            x1 = std::max({x1, c.a.x + c.radius, c.b.x + c.radius});
            y0 = std::min({y0, c.a.y - c.radius, c.b.y - c.radius});
            y1 = std::max({y1, c.a.y + c.radius, c.b.y + c.radius});
        };
        add(wrist);
        for (const Capsule& c : fingers)
            add(c);
        return {x0, y0, x1 - x0, y1 - y0};
    }
};

using DistanceFn = std::function<double(cv::Point2d)>;
using ColourFn = std::function<cv::Vec3f(cv::Point2d, double distance)>;

// Samples distance and colour at texel centres over extent plus the margin.
Sprite sample(const cv::Rect2d& extent, const DistanceFn& distance, const ColourFn& colour) {
    Sprite s;
    s.texels_per_unit = texels_per_unit;
    s.extent = extent;
    const int cols =
        static_cast<int>(std::ceil((extent.width + 2 * margin_units) * texels_per_unit));
    const int rows =
        static_cast<int>(std::ceil((extent.height + 2 * margin_units) * texels_per_unit));
    s.origin = {(margin_units - extent.x) * texels_per_unit,
                (margin_units - extent.y) * texels_per_unit};
    s.sdf.create(rows, cols, CV_32F);
    s.colour.create(rows, cols, CV_32FC3);
    int inside = 0;
    for (int j = 0; j < rows; ++j) {
        auto* d_row = s.sdf.ptr<float>(j);
        auto* c_row = s.colour.ptr<cv::Vec3f>(j);
        for (int i = 0; i < cols; ++i) {
            const cv::Point2d p((i + 0.5 - s.origin.x) / texels_per_unit,
                                (j + 0.5 - s.origin.y) / texels_per_unit);
            const double d = distance(p);
            d_row[i] = static_cast<float>(d);
            c_row[i] = colour(p, d);
            inside += d <= 0 ? 1 : 0;
        }
    }
    s.area = inside / (texels_per_unit * texels_per_unit);
    return s;
}

cv::Vec3f scaled(const Colour& c, double factor) {
    return {static_cast<float>(c.b * factor), static_cast<float>(c.g * factor),
            static_cast<float>(c.r * factor)};
}

Sprite make_sphere(const Colour& colour) {
    // Matte (Lambertian) under a light from the upper left, in front: the lit side reaches
    // `colour`, the far side keeps 30% from ambient light.
    const cv::Vec3d light = cv::normalize(cv::Vec3d(-0.5, -0.6, 0.62));
    auto shade = [&](cv::Point2d p, double) {
        const double rho = std::min(std::hypot(p.x, p.y) / 0.5, 1.0);
        const double nz = std::sqrt(std::max(0.0, 1 - rho * rho));
        const double len = std::max(std::hypot(p.x, p.y), 1e-9);
        const double nx = p.x / len * rho;
        const double ny = p.y / len * rho;
        const double lambert = std::max(0.0, nx * light[0] + ny * light[1] + nz * light[2]);
        return scaled(colour, 0.30 + 0.70 * lambert);
    };
    Sprite s = sample(
        {-0.5, -0.5, 1, 1}, [](cv::Point2d p) { return std::hypot(p.x, p.y) - 0.5; }, shade);
    s.rotates = false;
    return s;
}

Sprite make_hand(const Colour& colour, double spread) {
    // Every spread in the fanned hand's units: the same hand, not one rescaled to its height.
    const HandShape fanned;
    const cv::Rect2d f = fanned.bounds();
    const cv::Point2d centre(f.x + f.width / 2, f.y + f.height / 2);
    const double unit = f.height;
    const HandShape raw(spread);
    const cv::Rect2d b = raw.bounds();
    auto distance = [&](cv::Point2d p) { return raw.distance(p * unit + centre) / unit; };
    // Evenly coloured; slightly brighter toward the fingertips (light from above) and a
    // little darker right at the outline, where a real hand curves away.
    auto shade = [&](cv::Point2d p, double d) {
        const double rim = 1 - 0.08 * (1 - smoothstep(0, 0.03, -d));
        return scaled(colour, (1 - 0.05 * p.y) * rim);
    };
    const cv::Rect2d extent((b.x - centre.x) / unit, (b.y - centre.y) / unit, b.width / unit,
                            b.height / unit);
    Sprite s = sample(extent, distance, shade);
    s.rotates = true;
    s.wrist = (raw.wrist.b - centre) / unit;
    s.wrist_radius = raw.wrist.radius / unit;
    return s;
}

}  // namespace

Sprite make_sprite(Target target, const Colour& colour, double spread) {
    switch (target) {
        case Target::sphere:
            return make_sphere(colour);
        case Target::hand:
            return make_hand(colour, spread);
    }
    return make_sphere(colour);
}

std::shared_ptr<const Sprite> shared_sprite(Target target, const Colour& colour, double spread) {
    using Key = std::tuple<Target, double, double, double, double>;
    static std::mutex mutex;
    static std::map<Key, std::shared_ptr<const Sprite>> cache;
    const Key key{target, colour.b, colour.g, colour.r, target == Target::hand ? spread : 1.0};
    const std::lock_guard lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
    // Bounded, for callers that sweep colours; a hand that moves its fingers takes
    // 2 spread_levels + 1.
    if (cache.size() >= 128) cache.clear();
    auto sprite = std::make_shared<const Sprite>(make_sprite(target, colour, spread));
    cache.emplace(key, sprite);
    return sprite;
}

Colour default_colour(Target target, Background background) {
    switch (target) {
        case Target::sphere:
            return {58, 58, 62};
        case Target::hand:
            // Blue paper contrasts with the white board; skin stands out less in a room, as in
            // the paper's real world test.
            return background == Background::plain ? Colour{168, 82, 32} : Colour{128, 160, 214};
    }
    return {58, 58, 62};
}

}  // namespace raypoint::scene
