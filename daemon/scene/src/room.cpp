// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "background.hpp"
#include "rng.hpp"
#include "room_paint.hpp"

namespace raypoint::scene {
namespace {

using paint::Texture;

// Builds a room as a webcam on a desk sees it: a wall with a window, a door, pictures and
// shelves, furniture standing on the floor. Sizes scale with the frame's height.
class Room {
  public:
    Room(cv::Size size, std::uint64_t seed)
        : canvas_(size, CV_8UC3),
          rng_(seed),
          w_(size.width),
          h_(size.height),
          px_(size.height / 480.0) {}

    cv::Mat build() {
        floor_y_ = static_cast<int>(h_ * rng_.uniform(0.74, 0.86));
        wall();
        floor();
        if (rng_.chance(0.6)) window();
        if (rng_.chance(0.4)) door();
        for (int i = rng_.integer(3, 6); i > 0; --i)
            picture();
        for (int i = rng_.integer(0, 2); i > 0; --i)
            wall_shelf();
        for (int i = rng_.integer(1, 3); i > 0; --i)
            bookshelf();
        for (int i = rng_.integer(2, 4); i > 0; --i)
            furniture();
        for (int i = rng_.integer(1, 3); i > 0; --i)
            boxes();
        for (int i = rng_.integer(1, 3); i > 0; --i)
            plant();
        if (rng_.chance(0.7)) lamp();
        return canvas_;
    }

  private:
    int px(double pixels_at_480) const {
        return std::max(1, static_cast<int>(std::lround(pixels_at_480 * px_)));
    }
    int offset(double pixels_at_480) const {
        return static_cast<int>(std::lround(pixels_at_480 * px_));
    }
    int x_at(double fraction) const { return static_cast<int>(std::lround(fraction * w_)); }
    int y_at(double fraction) const { return static_cast<int>(std::lround(fraction * h_)); }

    void wall() {
        const cv::Scalar colour = paint::wall_colour(rng_);
        const Texture texture = rng_.chance(0.25) ? Texture::stripes : Texture::flat;
        paint::surface(canvas_, {0, 0, w_, floor_y_}, colour, texture, rng_, 0);
        // Skirting board along the floor line.
        const cv::Scalar skirting =
            rng_.chance(0.5) ? cv::Scalar(235, 235, 235) : paint::wood_colour(rng_);
        paint::surface(canvas_, {0, floor_y_ - px(10), w_, px(10)}, skirting, Texture::flat, rng_,
                       1);
    }

    void floor() {
        const bool carpet = rng_.chance(0.4);
        const cv::Scalar colour = carpet ? paint::any_colour(rng_) : paint::wood_colour(rng_);
        const cv::Rect area(0, floor_y_, w_, h_ - floor_y_);
        paint::surface(canvas_, area, colour, carpet ? Texture::fabric : Texture::grain, rng_, 0);
        if (carpet) return;
        // Plank seams running away from the camera.
        for (int x = rng_.integer(0, px(60)); x < w_; x += px(rng_.uniform(50, 90))) {
            cv::line(canvas_, {x, floor_y_}, {x + (x - w_ / 2) / 3, h_}, paint::scaled(colour, 0.6),
                     px(1), cv::LINE_AA);
        }
    }

    void window() {
        const cv::Rect frame(x_at(rng_.uniform(0.05, 0.7)), y_at(rng_.uniform(0.04, 0.14)),
                             x_at(rng_.uniform(0.18, 0.3)), y_at(rng_.uniform(0.3, 0.42)));
        // Curtains either side, then the bright sky with a green tree line, then the frame.
        const cv::Scalar curtain = paint::vivid_colour(rng_);
        const int curtain_w = px(rng_.uniform(20, 40));
        const cv::Rect drop(frame.x - curtain_w, frame.y - px(8), frame.width + 2 * curtain_w,
                            frame.height + px(30));
        paint::surface(canvas_, drop, curtain, Texture::stripes, rng_, 1);
        const cv::Scalar sky(rng_.uniform(235, 252), rng_.uniform(228, 245),
                             rng_.uniform(215, 235));
        paint::surface(canvas_, frame, sky, Texture::flat, rng_, 0);
        for (int i = 0; i < 6; ++i) {
            paint::blob(
                canvas_,
                {frame.x + static_cast<int>(rng_.uniform(0, frame.width)),
                 frame.y + frame.height - px(rng_.uniform(0, 15))},
                {px(rng_.uniform(12, 30)), px(rng_.uniform(10, 25))},
                paint::hsv(rng_.uniform(80, 140), rng_.uniform(0.4, 0.7), rng_.uniform(0.3, 0.6)));
        }
        const cv::Scalar bars =
            rng_.chance(0.5) ? cv::Scalar(240, 240, 240) : paint::wood_colour(rng_);
        cv::rectangle(canvas_, frame, bars, px(7));
        cv::line(canvas_, {frame.x + frame.width / 2, frame.y},
                 {frame.x + frame.width / 2, frame.br().y}, bars, px(5));
        cv::line(canvas_, {frame.x, frame.y + frame.height / 2},
                 {frame.br().x, frame.y + frame.height / 2}, bars, px(5));
    }

    void door() {
        const int width = x_at(rng_.uniform(0.14, 0.2));
        const cv::Rect door(x_at(rng_.uniform(0, 0.85)), y_at(rng_.uniform(0.02, 0.12)), width, 0);
        const cv::Rect leaf(door.x, door.y, width, floor_y_ - door.y);
        const cv::Scalar colour =
            rng_.chance(0.5) ? paint::wood_colour(rng_) : cv::Scalar(225, 228, 230);
        paint::surface(canvas_, leaf, colour, Texture::grain, rng_, px(3));
        // Panels and a handle.
        const cv::Scalar inset = paint::scaled(colour, 0.8);
        cv::rectangle(
            canvas_,
            {leaf.x + width / 6, leaf.y + leaf.height / 12, width * 2 / 3, leaf.height / 3}, inset,
            px(2), cv::LINE_AA);
        cv::rectangle(
            canvas_,
            {leaf.x + width / 6, leaf.y + leaf.height / 2, width * 2 / 3, leaf.height * 5 / 12},
            inset, px(2), cv::LINE_AA);
        cv::circle(canvas_, {leaf.x + width * 5 / 6, leaf.y + leaf.height * 11 / 20}, px(5),
                   cv::Scalar(60, 170, 200), cv::FILLED, cv::LINE_AA);
    }

    void picture() {
        const cv::Rect frame(x_at(rng_.uniform(0, 0.9)), y_at(rng_.uniform(0.03, 0.35)),
                             x_at(rng_.uniform(0.08, 0.22)), y_at(rng_.uniform(0.1, 0.25)));
        const cv::Scalar border = rng_.chance(0.5) ? paint::hsv(0, 0, rng_.uniform(0.05, 0.95))
                                                   : paint::wood_colour(rng_);
        paint::surface(canvas_, frame, border, Texture::flat, rng_, 1);
        const int mat = px(rng_.uniform(4, 10));
        const cv::Rect inner(frame.x + mat, frame.y + mat, frame.width - 2 * mat,
                             frame.height - 2 * mat);
        if (inner.width <= 2 || inner.height <= 2) return;
        if (rng_.chance(0.4)) {
            // A landscape: sky over hills.
            const cv::Scalar sky = paint::hsv(rng_.uniform(190, 230), rng_.uniform(0.2, 0.6), 0.9);
            paint::surface(canvas_, inner, sky, Texture::flat, rng_, 0);
            const cv::Rect ground(inner.x, inner.y + inner.height * 3 / 5, inner.width,
                                  inner.height * 2 / 5);
            paint::surface(canvas_, ground,
                           paint::hsv(rng_.uniform(60, 140), 0.6, rng_.uniform(0.3, 0.6)),
                           Texture::flat, rng_, 0);
            paint::blob(canvas_, {inner.x + inner.width / 4, inner.y + inner.height / 4},
                        {px(6), px(6)}, cv::Scalar(120, 230, 250));
        } else {
            paint::surface(canvas_, inner, paint::any_colour(rng_), paint::any_texture(rng_), rng_,
                           0);
            for (int i = rng_.integer(0, 3); i > 0; --i) {
                paint::blob(canvas_,
                            {inner.x + static_cast<int>(rng_.uniform(0, inner.width)),
                             inner.y + static_cast<int>(rng_.uniform(0, inner.height))},
                            {px(rng_.uniform(5, 18)), px(rng_.uniform(5, 18))},
                            paint::vivid_colour(rng_));
            }
        }
    }

    // A board on brackets with a row of things on it: books, boxes, vases.
    void wall_shelf() {
        const int width = x_at(rng_.uniform(0.15, 0.35));
        const cv::Point at(x_at(rng_.uniform(0, 0.85)), y_at(rng_.uniform(0.18, 0.5)));
        const cv::Scalar wood = paint::wood_colour(rng_);
        int x = at.x + px(6);
        while (x < at.x + width - px(14)) {
            const int w = px(rng_.uniform(8, 30));
            const int h = px(rng_.uniform(14, 50));
            const cv::Rect thing(x, at.y - h, std::min(w, at.x + width - x), h);
            if (rng_.chance(0.3)) {
                paint::blob(canvas_, {thing.x + thing.width / 2, thing.y + thing.height / 2},
                            {thing.width / 2, thing.height / 2}, paint::any_colour(rng_));
            } else {
                paint::surface(canvas_, thing, paint::any_colour(rng_), paint::any_texture(rng_),
                               rng_, 1);
            }
            x += w + px(rng_.uniform(0, 12));
        }
        paint::surface(canvas_, {at.x, at.y, width, px(8)}, wood, Texture::grain, rng_, 1);
        for (const int bx : {at.x + width / 6, at.x + width * 5 / 6}) {
            cv::line(canvas_, {bx, at.y + px(8)}, {bx, at.y + px(22)}, cv::Scalar(40, 40, 40),
                     px(3));
        }
    }

    // Cardboard and storage boxes stacked on the floor.
    void boxes() {
        int x = x_at(rng_.uniform(-0.05, 0.9));
        int bottom = floor_y_ + static_cast<int>((h_ - floor_y_) * rng_.uniform(0.3, 1.0));
        for (int i = rng_.integer(1, 3); i > 0; --i) {
            const int w = px(rng_.uniform(40, 110));
            const int h = px(rng_.uniform(30, 70));
            const cv::Scalar colour = rng_.chance(0.5)
                                          ? paint::hsv(30, 0.45, rng_.uniform(0.5, 0.75))
                                          : paint::any_colour(rng_);
            paint::surface(canvas_, {x, bottom - h, w, h}, colour, paint::any_texture(rng_), rng_,
                           px(2));
            cv::line(canvas_, {x, bottom - h + h / 4}, {x + w, bottom - h + h / 4},
                     paint::scaled(colour, 0.6), px(2));
            x += px(rng_.uniform(-20, 20));
            bottom -= h;
        }
    }

    void bookshelf() {
        const int width = x_at(rng_.uniform(0.15, 0.3));
        const cv::Rect shelf(x_at(rng_.uniform(-0.05, 0.9)), y_at(rng_.uniform(0.08, 0.3)), width,
                             0);
        const cv::Rect body(shelf.x, shelf.y, width, floor_y_ + px(8) - shelf.y);
        const cv::Scalar wood = paint::wood_colour(rng_);
        paint::surface(canvas_, body, paint::scaled(wood, 0.55), Texture::flat, rng_, px(2));
        const int side = px(7);
        const int level = std::max(px(40), body.height / rng_.integer(3, 5));
        for (int top = body.y + side; top + px(20) < body.br().y; top += level) {
            const int bottom = std::min(top + level - side, body.br().y - side);
            books({body.x + side, top, body.width - 2 * side, bottom - top});
            paint::surface(canvas_, {body.x, bottom, body.width, side}, wood, Texture::grain, rng_,
                           1);
        }
        paint::surface(canvas_, {body.x, body.y, side, body.height}, wood, Texture::grain, rng_, 1);
        paint::surface(canvas_, {body.br().x - side, body.y, side, body.height}, wood,
                       Texture::grain, rng_, 1);
    }

    void books(cv::Rect space) {
        int x = space.x + px(rng_.uniform(0, 6));
        while (x < space.br().x - px(4)) {
            if (rng_.chance(0.12)) {
                x += px(rng_.uniform(8, 30));  // a gap, or a leaning book's space
                continue;
            }
            const int width = px(rng_.uniform(5, 16));
            const int height = static_cast<int>(space.height * rng_.uniform(0.6, 0.97));
            const cv::Rect book(x, space.br().y - height, std::min(width, space.br().x - x),
                                height);
            const cv::Scalar colour = paint::any_colour(rng_);
            paint::surface(canvas_, book, colour, Texture::flat, rng_, 1);
            if (rng_.chance(0.5) && book.height > px(20)) {
                const int band = book.y + static_cast<int>(book.height * rng_.uniform(0.1, 0.3));
                cv::line(canvas_, {book.x + 1, band}, {book.br().x - 2, band},
                         rng_.chance(0.5) ? cv::Scalar(70, 200, 230) : cv::Scalar(240, 240, 240),
                         px(2));
            }
            x += width + px(rng_.uniform(0, 2));
        }
    }

    void furniture() {
        const int width = x_at(rng_.uniform(0.15, 0.4));
        const int height = y_at(rng_.uniform(0.15, 0.35));
        const int x = x_at(rng_.uniform(-0.1, 0.95));
        const int bottom = floor_y_ + static_cast<int>((h_ - floor_y_) * rng_.uniform(0.2, 0.9));
        const cv::Rect body(x, bottom - height, width, height);
        const double kind = rng_.uniform();
        if (kind < 0.35) {
            // Sofa or armchair: fabric with seat cushions and arms.
            const cv::Scalar colour = paint::any_colour(rng_);
            paint::surface(canvas_, body, colour, Texture::fabric, rng_, px(2));
            const int arm = width / 8;
            paint::surface(canvas_, {body.x, body.y + height / 4, arm, height * 3 / 4},
                           paint::scaled(colour, 0.85), Texture::fabric, rng_, px(2));
            paint::surface(canvas_, {body.br().x - arm, body.y + height / 4, arm, height * 3 / 4},
                           paint::scaled(colour, 0.85), Texture::fabric, rng_, px(2));
            cv::line(canvas_, {body.x + arm, body.y + height / 2},
                     {body.br().x - arm, body.y + height / 2}, paint::scaled(colour, 0.5), px(2),
                     cv::LINE_AA);
        } else if (kind < 0.7) {
            // Cabinet with drawers and knobs.
            const cv::Scalar colour =
                rng_.chance(0.6) ? paint::wood_colour(rng_) : paint::any_colour(rng_);
            paint::surface(canvas_, body, colour, Texture::grain, rng_, px(2));
            const int drawers = rng_.integer(2, 4);
            for (int i = 1; i <= drawers; ++i) {
                const int y = body.y + height * i / (drawers + 1);
                cv::line(canvas_, {body.x, y}, {body.br().x, y}, paint::scaled(colour, 0.45),
                         px(2));
                cv::circle(canvas_, {body.x + width / 2, y - height / (2 * (drawers + 1))}, px(4),
                           cv::Scalar(190, 195, 200), cv::FILLED, cv::LINE_AA);
            }
        } else {
            // Desk with a monitor and small things on it.
            const cv::Scalar colour = paint::wood_colour(rng_);
            paint::surface(canvas_, {body.x, body.y, width, px(12)}, colour, Texture::grain, rng_,
                           1);
            paint::surface(canvas_, {body.x + px(6), body.y + px(12), px(10), height - px(12)},
                           paint::scaled(colour, 0.7), Texture::flat, rng_, 1);
            paint::surface(canvas_,
                           {body.br().x - px(16), body.y + px(12), px(10), height - px(12)},
                           paint::scaled(colour, 0.7), Texture::flat, rng_, 1);
            const cv::Rect screen(body.x + width / 4, body.y - px(rng_.uniform(70, 110)), width / 2,
                                  px(rng_.uniform(55, 95)));
            paint::surface(canvas_, screen, cv::Scalar(30, 30, 32), Texture::flat, rng_, 0);
            const cv::Rect glow(screen.x + px(5), screen.y + px(5), screen.width - px(10),
                                screen.height - px(10));
            paint::surface(canvas_, glow, paint::hsv(rng_.uniform(180, 240), 0.5, 0.8),
                           paint::any_texture(rng_), rng_, 0);
            paint::surface(canvas_,
                           {screen.x + screen.width / 2 - px(5), screen.br().y, px(10),
                            body.y - screen.br().y},
                           cv::Scalar(40, 40, 40), Texture::flat, rng_, 0);
            for (int i = rng_.integer(1, 3); i > 0; --i) {
                const int mug_x = body.x + static_cast<int>(rng_.uniform(0, width - px(20)));
                paint::surface(canvas_, {mug_x, body.y - px(22), px(16), px(22)},
                               paint::vivid_colour(rng_), Texture::flat, rng_, 1);
            }
        }
    }

    void plant() {
        const cv::Point base(x_at(rng_.uniform(0.02, 0.98)), floor_y_ + px(rng_.uniform(10, 40)));
        const cv::Scalar pot =
            rng_.chance(0.5) ? paint::hsv(15, 0.7, 0.6) : paint::any_colour(rng_);
        const std::vector<cv::Point> shape{{base.x - px(22), base.y - px(45)},
                                           {base.x + px(22), base.y - px(45)},
                                           {base.x + px(15), base.y},
                                           {base.x - px(15), base.y}};
        cv::fillConvexPoly(canvas_, shape, pot, cv::LINE_AA);
        const int leaves = rng_.integer(6, 12);
        for (int i = 0; i < leaves; ++i) {
            const double angle = rng_.uniform(-2.6, -0.5);
            const double reach = rng_.uniform(30, 90);
            const cv::Point tip(base.x + offset(reach * std::cos(angle)),
                                base.y - px(45) + offset(reach * std::sin(angle)));
            paint::blob(canvas_, tip, {px(rng_.uniform(10, 22)), px(rng_.uniform(6, 14))},
                        paint::hsv(rng_.uniform(75, 150), rng_.uniform(0.4, 0.8),
                                   rng_.uniform(0.25, 0.65)));
        }
    }

    void lamp() {
        const int x = x_at(rng_.uniform(0.05, 0.95));
        const int top = y_at(rng_.uniform(0.15, 0.4));
        cv::line(canvas_, {x, top}, {x, floor_y_ + px(20)}, cv::Scalar(50, 50, 55), px(4),
                 cv::LINE_AA);
        const cv::Scalar shade(rng_.uniform(170, 235), rng_.uniform(200, 245),
                               rng_.uniform(220, 252));
        const std::vector<cv::Point> cone{{x - px(22), top - px(35)},
                                          {x + px(22), top - px(35)},
                                          {x + px(38), top + px(5)},
                                          {x - px(38), top + px(5)}};
        cv::fillConvexPoly(canvas_, cone, shade, cv::LINE_AA);
        cv::polylines(canvas_, cone, true, paint::scaled(shade, 0.7), px(1), cv::LINE_AA);
    }

    cv::Mat canvas_;
    Rng rng_;
    int w_;
    int h_;
    double px_;  // pixels per pixel of a 480-line frame
    int floor_y_ = 0;
};

}  // namespace

cv::Mat make_room(cv::Size size, std::uint64_t seed) {
    const cv::Mat canvas = Room(size, seed).build();
    cv::Mat room;
    canvas.convertTo(room, CV_32FC3);
    // A ceiling light somewhere above: the room is brighter around it, darker in far corners.
    Rng rng(mix_seed(seed, 7));
    paint::ceiling_light(room, rng, 0.8, 0.3);
    // The lens is not perfectly sharp.
    cv::GaussianBlur(room, room, cv::Size(), 0.7 * size.height / 480.0);
    return room;
}

}  // namespace raypoint::scene
