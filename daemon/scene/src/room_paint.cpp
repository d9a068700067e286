// SPDX-License-Identifier: MIT
#include "room_paint.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace raypoint::scene::paint {

cv::Scalar hsv(double hue, double saturation, double value) {
    const double c = value * saturation;
    const double h = std::fmod(hue, 360.0) / 60.0;
    const double x = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
    double r = 0, g = 0, b = 0;
    if (h < 1) {
        r = c, g = x;
    } else if (h < 2) {
        r = x, g = c;
    } else if (h < 3) {
        g = c, b = x;
    } else if (h < 4) {
        g = x, b = c;
    } else if (h < 5) {
        r = x, b = c;
    } else {
        r = c, b = x;
    }
    const double m = value - c;
    return {255 * (b + m), 255 * (g + m), 255 * (r + m)};
}

cv::Scalar wall_colour(Rng& rng) {
    // Painted walls: pale and not very saturated, sometimes a stronger accent wall.
    if (rng.chance(0.2))
        return hsv(rng.uniform(0, 360), rng.uniform(0.25, 0.45), rng.uniform(0.45, 0.7));
    return hsv(rng.uniform(0, 360), rng.uniform(0.05, 0.25), rng.uniform(0.6, 0.85));
}

cv::Scalar wood_colour(Rng& rng) {
    return hsv(rng.uniform(18, 38), rng.uniform(0.35, 0.65), rng.uniform(0.3, 0.75));
}

cv::Scalar vivid_colour(Rng& rng) {
    return hsv(rng.uniform(0, 360), rng.uniform(0.45, 0.9), rng.uniform(0.3, 0.95));
}

cv::Scalar any_colour(Rng& rng) {
    const double pick = rng.uniform();
    if (pick < 0.45) return vivid_colour(rng);
    if (pick < 0.8) return hsv(rng.uniform(0, 360), rng.uniform(0.1, 0.4), rng.uniform(0.4, 0.9));
    return hsv(rng.uniform(0, 360), rng.uniform(0, 0.5), rng.uniform(0.08, 0.3));
}

cv::Scalar scaled(const cv::Scalar& colour, double factor) {
    return {std::min(255.0, colour[0] * factor), std::min(255.0, colour[1] * factor),
            std::min(255.0, colour[2] * factor)};
}

Texture any_texture(Rng& rng) {
    switch (rng.integer(0, 5)) {
        case 0:
            return Texture::stripes;
        case 1:
            return Texture::checker;
        case 2:
            return Texture::fabric;
        case 3:
            return Texture::grain;
        default:
            return Texture::flat;
    }
}

namespace {

void pattern(cv::Mat& area, const cv::Scalar& colour, Texture texture, Rng& rng) {
    switch (texture) {
        case Texture::flat:
            return;
        case Texture::stripes: {
            // Bold stripes in a second colour, vertical or horizontal.
            const cv::Scalar other = rng.chance(0.5) ? any_colour(rng) : scaled(colour, 0.6);
            const int period = rng.integer(6, 24);
            const int width = rng.integer(2, period / 2 + 1);
            const bool vertical = rng.chance(0.5);
            const int length = vertical ? area.cols : area.rows;
            for (int k = 0; k < length; k += period) {
                const cv::Rect band =
                    vertical ? cv::Rect(k, 0, width, area.rows) : cv::Rect(0, k, area.cols, width);
                area(band & cv::Rect(0, 0, area.cols, area.rows)).setTo(other);
            }
            return;
        }
        case Texture::checker: {
            const cv::Scalar other = rng.chance(0.5) ? any_colour(rng) : scaled(colour, 1.35);
            const int cell = rng.integer(6, 20);
            for (int y = 0; y < area.rows; y += cell) {
                for (int x = (y / cell) % 2 == 0 ? 0 : cell; x < area.cols; x += 2 * cell) {
                    area(cv::Rect(x, y, cell, cell) & cv::Rect(0, 0, area.cols, area.rows))
                        .setTo(other);
                }
            }
            return;
        }
        case Texture::fabric: {
            // Woven look: fine noise, slightly stretched.
            cv::Mat noise(area.size(), CV_16SC3);
            cv::RNG cv_rng(rng.next());
            cv_rng.fill(noise, cv::RNG::NORMAL, 0, 14);
            cv::blur(noise, noise, cv::Size(3, 1));
            cv::Mat widened;
            area.convertTo(widened, CV_16SC3);
            widened += noise;
            widened.convertTo(area, CV_8UC3);
            return;
        }
        case Texture::grain: {
            // Wood grain: wavy darker lines along the longer side.
            const cv::Scalar line_colour = scaled(colour, 0.72);
            const bool horizontal = area.cols > area.rows;
            const int across = horizontal ? area.rows : area.cols;
            const int along = horizontal ? area.cols : area.rows;
            const double wave = rng.uniform(0.01, 0.04);
            for (int k = rng.integer(2, 6); k < across; k += rng.integer(3, 9)) {
                std::vector<cv::Point> line;
                const double phase = rng.uniform(0, 6.28);
                for (int s = 0; s <= along; s += 8) {
                    const int off =
                        k + static_cast<int>(std::lround(3 * std::sin(wave * s + phase)));
                    line.push_back(horizontal ? cv::Point(s, off) : cv::Point(off, s));
                }
                cv::polylines(area, line, false, line_colour, 1, cv::LINE_AA);
            }
            return;
        }
    }
}

}  // namespace

void surface(cv::Mat& canvas, cv::Rect rect, const cv::Scalar& colour, Texture texture, Rng& rng,
             int edge) {
    rect &= cv::Rect(0, 0, canvas.cols, canvas.rows);
    if (rect.empty()) return;
    cv::Mat area = canvas(rect);
    area.setTo(colour);
    pattern(area, colour, texture, rng);
    // Top-lit: a few percent brighter at the top, darker at the bottom.
    for (int y = 0; y < area.rows; ++y) {
        const double light = 1.06 - 0.14 * y / std::max(1, area.rows - 1);
        cv::Mat row = area.row(y);
        row.convertTo(row, -1, light);
    }
    if (edge > 0)
        cv::rectangle(area, cv::Rect(0, 0, area.cols, area.rows), scaled(colour, 0.45), edge);
}

void ceiling_light(cv::Mat& light, Rng& rng, double base, double boost) {
    const double lx = rng.uniform(0.2, 0.8) * light.cols;
    const double ly = rng.uniform(-0.3, 0.2) * light.rows;
    const double reach = light.rows * 1.2;
    for (int y = 0; y < light.rows; ++y) {
        auto* row = light.ptr<cv::Vec3f>(y);
        for (int x = 0; x < light.cols; ++x) {
            const double d2 = ((x - lx) * (x - lx) + (y - ly) * (y - ly)) / (reach * reach);
            row[x] *= static_cast<float>(base + boost * std::exp(-d2));
        }
    }
}

void blob(cv::Mat& canvas, cv::Point centre, cv::Size axes, const cv::Scalar& colour) {
    cv::ellipse(canvas, centre, axes, 0, 0, 360, colour, cv::FILLED, cv::LINE_AA);
    const cv::Point lit(centre.x - axes.width / 5, centre.y - axes.height / 5);
    cv::ellipse(canvas, lit, cv::Size(axes.width * 3 / 5, axes.height * 3 / 5), 0, 0, 360,
                scaled(colour, 1.15), cv::FILLED, cv::LINE_AA);
    cv::ellipse(canvas, centre, axes, 0, 0, 360, scaled(colour, 0.55), 1, cv::LINE_AA);
}

}  // namespace raypoint::scene::paint
