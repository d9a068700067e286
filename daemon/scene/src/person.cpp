// SPDX-License-Identifier: MIT
#include "person.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "rng.hpp"

namespace raypoint::scene {
namespace {

constexpr double two_pi = 6.283185307179586;
// Periods (s) and amplitudes (pixels at 480 lines) of the small motions of a seated person.
constexpr double breath_seconds = 4.0;
constexpr double breath_px = 2.5;
constexpr double turn_seconds = 7.0;
constexpr double turn_px = 9.0;  // the face's features across the head
constexpr double sway_seconds = 11.0;
constexpr double sway_px = 5.0;
constexpr double nod_seconds = 5.3;
constexpr double nod_px = 3.0;

cv::Point at(double x, double y) {
    return {static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
}

cv::Size axes(double a, double b) {
    return {std::max(1, static_cast<int>(std::lround(a))),
            std::max(1, static_cast<int>(std::lround(b)))};
}

}  // namespace

Person::Person(cv::Size frame, const Colour& skin, std::uint64_t seed)
    : frame_(frame), px_(frame.height / 480.0) {
    Rng rng(seed);
    // The target's skin, a shade darker or lighter and a little redder or yellower.
    const double shade = rng.uniform(0.82, 1.0);
    skin_ = cv::Scalar(skin.b * shade * rng.uniform(0.92, 1.04), skin.g * shade,
                       skin.r * shade * rng.uniform(0.97, 1.03));
    const double dark = rng.uniform(0.12, 0.35);
    hair_ = cv::Scalar(60 * dark, 85 * dark, 110 * dark);
    const double pick = rng.uniform();
    shirt_ =
        pick < 0.4   ? cv::Scalar(rng.uniform(40, 200), rng.uniform(40, 160), rng.uniform(30, 120))
        : pick < 0.7 ? cv::Scalar::all(rng.uniform(40, 220))
                     : cv::Scalar(rng.uniform(30, 120), rng.uniform(40, 140), rng.uniform(60, 200));
    x_ = frame.width * rng.uniform(0.35, 0.65);
    head_ = frame.height * rng.uniform(0.3, 0.4);
    turn_phase_ = rng.uniform(0, two_pi);
    sway_phase_ = rng.uniform(0, two_pi);
    nod_phase_ = rng.uniform(0, two_pi);
}

void Person::draw(double t, const cv::Mat& vignette, cv::Mat& light) const {
    const double breath = breath_px * px_ * std::sin(two_pi * t / breath_seconds);
    const double turn = std::sin(two_pi * t / turn_seconds + turn_phase_);
    const double sway = sway_px * px_ * std::sin(two_pi * t / sway_seconds + sway_phase_);
    const double nod = nod_px * px_ * std::sin(two_pi * t / nod_seconds + nod_phase_);
    const double h = 480 * px_;
    const double cx = x_ + sway;
    const double head_y = head_ - breath + nod;
    const double head_rx = 0.085 * h;
    const double head_ry = 0.115 * h;
    const double shoulders = head_y + head_ry + 0.07 * h - breath;
    const double face_x = cx + turn * turn_px * px_;

    // The outline (coverage, anti-aliased) and the colours (hard-edged, each shape a little wider,
    // so that the outline's anti-aliasing blends the person's colour, not black, into the room).
    cv::Mat colour(frame_, CV_8UC3, skin_);
    cv::Mat cover(frame_, CV_8U, cv::Scalar(0));
    const auto both = [&](auto&& shape) {
        shape(colour, 3, cv::LINE_8);
        shape(cover, 0, cv::LINE_AA);
    };
    const cv::Scalar white(255);
    // Shirt: shoulders rounded into arms that leave the frame at the bottom.
    const std::vector<cv::Point> torso{
        at(cx - 0.13 * h, shoulders - 0.01 * h), at(cx + 0.13 * h, shoulders - 0.01 * h),
        at(cx + 0.30 * h, shoulders + 0.08 * h), at(cx + 0.36 * h, frame_.height + 2),
        at(cx - 0.36 * h, frame_.height + 2),    at(cx - 0.30 * h, shoulders + 0.08 * h)};
    both([&](cv::Mat& m, int grow, int type) {
        const cv::Scalar c = m.channels() == 1 ? white : shirt_;
        cv::fillPoly(m, std::vector<std::vector<cv::Point>>{torso}, c, type);
        if (grow > 0) cv::polylines(m, torso, true, c, grow, type);
        for (const double side : {-1.0, 1.0}) {
            cv::ellipse(m, at(cx + side * 0.24 * h, shoulders + 0.09 * h),
                        axes(0.09 * h + grow, 0.09 * h + grow), 0, 0, 360, c, cv::FILLED, type);
        }
    });
    // Neck and head, then the ears.
    both([&](cv::Mat& m, int grow, int type) {
        const cv::Scalar c = m.channels() == 1 ? white : skin_;
        cv::ellipse(m, at(cx, shoulders - 0.03 * h), axes(0.05 * h + grow, 0.07 * h + grow), 0, 0,
                    360, c, cv::FILLED, type);
        cv::ellipse(m, at(cx, head_y), axes(head_rx + grow, head_ry + grow), 0, 0, 360, c,
                    cv::FILLED, type);
        for (const double side : {-1.0, 1.0}) {
            cv::ellipse(m,
                        at(cx + side * (head_rx - 0.004 * h) - turn * 0.01 * h, head_y + 0.01 * h),
                        axes(0.018 * h + grow, 0.03 * h + grow), 0, 0, 360, c, cv::FILLED, type);
        }
    });
    // Hair over the top of the head; the neck's shadow under the chin.
    cv::ellipse(cover, at(cx, head_y - 0.035 * h), axes(head_rx * 1.06, head_ry * 0.86), 0, 180,
                360, white, cv::FILLED, cv::LINE_AA);
    cv::ellipse(colour, at(cx, head_y - 0.035 * h), axes(head_rx * 1.06 + 3, head_ry * 0.86 + 3), 0,
                180, 360, hair_, cv::FILLED, cv::LINE_8);
    cv::ellipse(colour, at(cx, head_y - 0.03 * h), axes(head_rx * 1.02, head_ry * 0.55), 0, 180,
                360, hair_, cv::FILLED, cv::LINE_AA);
    cv::ellipse(colour, at(cx, shoulders - 0.055 * h), axes(0.05 * h, 0.02 * h), 0, 0, 180,
                skin_ * 0.8, cv::FILLED, cv::LINE_AA);
    // The face, turned: eyes, brows, nose and mouth shift across the head.
    const double eye_y = head_y + 0.005 * h;
    for (const double side : {-1.0, 1.0}) {
        const double ex = face_x + side * 0.035 * h;
        cv::ellipse(colour, at(ex, eye_y), axes(0.014 * h, 0.007 * h), 0, 0, 360,
                    cv::Scalar(235, 235, 235), cv::FILLED, cv::LINE_AA);
        cv::circle(colour, at(ex + turn * 0.004 * h, eye_y), std::max(1, int(0.006 * h)),
                   cv::Scalar(40, 50, 60), cv::FILLED, cv::LINE_AA);
        cv::line(colour, at(ex - 0.016 * h, eye_y - 0.02 * h),
                 at(ex + 0.016 * h, eye_y - 0.022 * h), hair_, std::max(1, int(0.006 * h)),
                 cv::LINE_AA);
    }
    cv::line(colour, at(face_x + 0.004 * h, eye_y + 0.01 * h),
             at(face_x + 0.01 * h, eye_y + 0.045 * h), skin_ * 0.78, std::max(1, int(0.005 * h)),
             cv::LINE_AA);
    cv::ellipse(colour, at(face_x, eye_y + 0.075 * h), axes(0.024 * h, 0.008 * h), 0, 0, 360,
                cv::Scalar(skin_[0] * 0.6, skin_[1] * 0.6, skin_[2] * 0.8), cv::FILLED,
                cv::LINE_AA);

    // Lit from above like the room, vignetted, blended by coverage.
    const cv::Rect box = cv::boundingRect(cover);
    const double top = box.y;
    const double span = std::max(1, box.height);
    for (int y = box.y; y < box.br().y; ++y) {
        const auto* c = colour.ptr<cv::Vec3b>(y);
        const auto* a = cover.ptr<std::uint8_t>(y);
        const auto* v = vignette.ptr<float>(y);
        auto* out = light.ptr<cv::Vec3f>(y);
        const auto lit = static_cast<float>(1.04 - 0.14 * (y - top) / span);
        for (int x = box.x; x < box.br().x; ++x) {
            if (a[x] == 0) continue;
            const float w = a[x] / 255.0f;
            const cv::Vec3f person = cv::Vec3f(c[x][0], c[x][1], c[x][2]) * (lit * v[x]);
            out[x] += w * (person - out[x]);
        }
    }
}

}  // namespace raypoint::scene
