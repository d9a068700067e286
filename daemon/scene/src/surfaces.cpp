// SPDX-License-Identifier: MIT
// Backgrounds close to a skin hand's colour: a warm painted wall and a wooden desk. What makes
// them hard for a tracker is the colour, so their texture is a real surface's: soft, with few
// strong edges.
#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "background.hpp"
#include "rng.hpp"
#include "room_paint.hpp"

namespace raypoint::scene {
namespace {

// Smooth unevenness of relative depth `depth`: a coarse random grid interpolated to the size.
cv::Mat unevenness(cv::Size size, cv::Size grid, double depth, Rng& rng) {
    cv::Mat coarse(grid, CV_32F);
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i)
            coarse.at<float>(j, i) = static_cast<float>(rng.uniform(-depth, depth));
    }
    cv::Mat smooth;
    cv::resize(coarse, smooth, size, 0, 0, cv::INTER_CUBIC);
    return smooth;
}

cv::Vec3f vec(const cv::Scalar& colour) {
    return {static_cast<float>(colour[0]), static_cast<float>(colour[1]),
            static_cast<float>(colour[2])};
}

}  // namespace

cv::Mat make_skin_wall(cv::Size size, std::uint64_t seed) {
    Rng rng(seed);
    const double px = size.height / 480.0;
    // Warm beige, peach or pink paint: a light skin's hue, a little paler and lighter, as
    // house paints of those names are.
    const cv::Scalar paint =
        paint::hsv(rng.uniform(8, 32), rng.uniform(0.18, 0.34), rng.uniform(0.80, 0.92));
    cv::Mat canvas(size, CV_8UC3, paint);
    // A few things on the wall: a framed picture, a light switch, a thin shelf with a book or two.
    for (int i = rng.integer(1, 2); i > 0; --i) {
        const cv::Rect frame(static_cast<int>(rng.uniform(0.02, 0.8) * size.width),
                             static_cast<int>(rng.uniform(0.05, 0.4) * size.height),
                             static_cast<int>(rng.uniform(0.1, 0.18) * size.width),
                             static_cast<int>(rng.uniform(0.12, 0.22) * size.height));
        paint::surface(canvas, frame, paint::wood_colour(rng), paint::Texture::flat, rng, 1);
        const int mat = std::max(2, static_cast<int>(8 * px));
        const cv::Rect inner(frame.x + mat, frame.y + mat, frame.width - 2 * mat,
                             frame.height - 2 * mat);
        paint::surface(canvas, inner, paint::any_colour(rng), paint::any_texture(rng), rng, 0);
    }
    const cv::Rect plate(static_cast<int>(rng.uniform(0.05, 0.9) * size.width),
                         static_cast<int>(rng.uniform(0.45, 0.6) * size.height),
                         std::max(4, static_cast<int>(22 * px)),
                         std::max(6, static_cast<int>(34 * px)));
    paint::surface(canvas, plate, cv::Scalar(232, 236, 238), paint::Texture::flat, rng, 1);
    if (rng.chance(0.6)) {
        const int shelf_y = static_cast<int>(rng.uniform(0.25, 0.4) * size.height);
        const int shelf_x = static_cast<int>(rng.uniform(0, 0.7) * size.width);
        const int width = static_cast<int>(rng.uniform(0.15, 0.3) * size.width);
        for (int x = shelf_x + static_cast<int>(6 * px); x < shelf_x + width / 3;) {
            const int w = std::max(3, static_cast<int>(rng.uniform(8, 16) * px));
            const int h = std::max(8, static_cast<int>(rng.uniform(30, 50) * px));
            paint::surface(canvas, {x, shelf_y - h, w, h}, paint::any_colour(rng),
                           paint::Texture::flat, rng, 1);
            x += w + 1;
        }
        paint::surface(canvas, {shelf_x, shelf_y, width, std::max(2, static_cast<int>(7 * px))},
                       paint::wood_colour(rng), paint::Texture::grain, rng, 1);
    }
    cv::Mat wall;
    canvas.convertTo(wall, CV_32FC3);
    // Paint on plaster: broad patches a few percent apart and a faint fine grain.
    const cv::Mat broad = unevenness(size, {6, 5}, 0.03, rng);
    cv::Mat fine(size, CV_32F);
    cv::RNG cv_rng(mix_seed(seed, 1));
    cv_rng.fill(fine, cv::RNG::NORMAL, 0, 1.5);
    cv::GaussianBlur(fine, fine, cv::Size(), 1.0 * px);
    for (int y = 0; y < size.height; ++y) {
        const auto* b = broad.ptr<float>(y);
        const auto* f = fine.ptr<float>(y);
        auto* out = wall.ptr<cv::Vec3f>(y);
        for (int x = 0; x < size.width; ++x)
            out[x] = out[x] * (1 + b[x]) + cv::Vec3f(f[x], f[x], f[x]);
    }
    paint::ceiling_light(wall, rng, 0.85, 0.2);
    cv::GaussianBlur(wall, wall, cv::Size(), 0.7 * px);
    return wall;
}

cv::Mat make_desk(cv::Size size, std::uint64_t seed) {
    Rng rng(seed);
    const double px = size.height / 480.0;
    // Varnished oak, beech, cherry or pine: a skin's hue, more saturated and mostly darker.
    const cv::Vec3f wood =
        vec(paint::hsv(rng.uniform(18, 34), rng.uniform(0.42, 0.62), rng.uniform(0.5, 0.74)));
    // Planks across the frame, each with its own shade and grain; the camera looks down at them.
    cv::Mat desk(size, CV_32FC3);
    const double plank = rng.uniform(110, 170) * px;
    const int planks = static_cast<int>(std::ceil(size.height / plank)) + 1;
    std::vector<double> shade(static_cast<std::size_t>(planks));
    std::vector<double> phase(static_cast<std::size_t>(planks));
    for (int i = 0; i < planks; ++i) {
        shade[static_cast<std::size_t>(i)] = rng.uniform(0.92, 1.06);
        phase[static_cast<std::size_t>(i)] = rng.uniform(0, 6.283185307179586);
    }
    const double period = rng.uniform(7, 12) * px;  // grain lines, ~2 px at 160x120
    const double wave = rng.uniform(0.004, 0.01) / px;
    const cv::Mat knots = unevenness(size, {9, 4}, 0.05, rng);
    for (int y = 0; y < size.height; ++y) {
        const int p = static_cast<int>(y / plank);
        const double along = y - p * plank;
        const auto* k = knots.ptr<float>(y);
        auto* out = desk.ptr<cv::Vec3f>(y);
        for (int x = 0; x < size.width; ++x) {
            const double bend =
                9 * px * std::sin(wave * x + phase[static_cast<std::size_t>(p)]) + 40 * px * k[x];
            const double grain = 0.5 + 0.5 * std::sin(6.283185307179586 * (along + bend) / period);
            const double light = shade[static_cast<std::size_t>(p)] * (1 - 0.09 * grain * grain);
            out[x] = wood * static_cast<float>(light * (1 + k[x]));
        }
        // The seam between two planks: a dark groove two pixels wide.
        if (along < 2 * px && p > 0) {
            for (int x = 0; x < size.width; ++x)
                out[x] *= 0.62f;
        }
    }
    // A few things on the desk: a sheet of paper, a pen, a mug from above.
    cv::Mat things(size, CV_8UC3, cv::Scalar::all(0));
    cv::Mat where(size, CV_8U, cv::Scalar(0));
    if (rng.chance(0.7)) {
        const cv::RotatedRect sheet({static_cast<float>(rng.uniform(0.1, 0.9) * size.width),
                                     static_cast<float>(rng.uniform(0.1, 0.9) * size.height)},
                                    {static_cast<float>(170 * px), static_cast<float>(230 * px)},
                                    static_cast<float>(rng.uniform(-30, 30)));
        cv::Point2f corners[4];
        sheet.points(corners);
        std::vector<cv::Point> polygon(corners, corners + 4);
        cv::fillConvexPoly(things, polygon, cv::Scalar(238, 240, 240), cv::LINE_AA);
        cv::fillConvexPoly(where, polygon, cv::Scalar(255), cv::LINE_AA);
    }
    const cv::Point pen(static_cast<int>(rng.uniform(0.05, 0.95) * size.width),
                        static_cast<int>(rng.uniform(0.05, 0.95) * size.height));
    const double pen_angle = rng.uniform(0, 3.14);
    const cv::Point pen_end(pen.x + static_cast<int>(110 * px * std::cos(pen_angle)),
                            pen.y + static_cast<int>(110 * px * std::sin(pen_angle)));
    const cv::Scalar pen_colour = paint::vivid_colour(rng);
    const int pen_width = std::max(2, static_cast<int>(7 * px));
    cv::line(things, pen, pen_end, pen_colour, pen_width, cv::LINE_AA);
    cv::line(where, pen, pen_end, cv::Scalar(255), pen_width, cv::LINE_AA);
    if (rng.chance(0.6)) {
        const cv::Point mug(static_cast<int>(rng.uniform(0.05, 0.95) * size.width),
                            static_cast<int>(rng.uniform(0.05, 0.95) * size.height));
        const int radius = std::max(4, static_cast<int>(38 * px));
        const cv::Scalar mug_colour = paint::any_colour(rng);
        cv::circle(things, mug, radius, mug_colour, cv::FILLED, cv::LINE_AA);
        cv::circle(things, mug, radius * 4 / 5, cv::Scalar(30, 45, 60), cv::FILLED, cv::LINE_AA);
        cv::circle(where, mug, radius, cv::Scalar(255), cv::FILLED, cv::LINE_AA);
    }
    for (int y = 0; y < size.height; ++y) {
        const auto* t = things.ptr<cv::Vec3b>(y);
        const auto* w = where.ptr<std::uint8_t>(y);
        auto* out = desk.ptr<cv::Vec3f>(y);
        for (int x = 0; x < size.width; ++x) {
            const float a = w[x] / 255.0f;
            out[x] = out[x] * (1 - a) + cv::Vec3f(t[x][0], t[x][1], t[x][2]) * a;
        }
    }
    paint::ceiling_light(desk, rng, 0.85, 0.2);
    cv::GaussianBlur(desk, desk, cv::Size(), 0.7 * px);
    return desk;
}

}  // namespace raypoint::scene
