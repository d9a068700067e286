// SPDX-License-Identifier: MIT
// The raster estimator's neck cut: the filled region loses what lies beyond a neck narrower
// than the target (RasterEstimator::cut_necks; EstimatorSettings::neck_radius).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "raster_estimator.hpp"

namespace raypoint::core::detail {

namespace {

// Marks: bit 0 the region, bit 1 its core, bit 2 near the main core, bit 3 near another core.
constexpr unsigned char in_region = 1;
constexpr unsigned char in_core = 2;
constexpr unsigned char near_main = 4;
constexpr unsigned char near_other = 8;

}  // namespace

// Erodes `from_bit` of marks_ by a square of half-side r into `to_bit` (every pixel of the square
// has from_bit), or dilates it (any pixel of the square has it), over the box [x0, x1) x
// [y0, y1), outside which no pixel has from_bit (nor does any off the image: cut_necks() leaves
// regions that reach the border alone). Separable, with running counts: a row pass into
// run_, then a column pass, a few instructions a pixel whatever r.
void RasterEstimator::morph(unsigned char from_bit, unsigned char to_bit, bool erode, int r, int x0,
                            int y0, int x1, int y1) noexcept {
    const int w = width_;
    const int full = 2 * r + 1;
    unsigned char* const marks = marks_.data();
    unsigned char* const run = run_.data();
    for (int y = y0; y < y1; ++y) {
        const unsigned char* row = marks + static_cast<std::ptrdiff_t>(y) * w;
        unsigned char* out = run + static_cast<std::ptrdiff_t>(y) * w;
        const auto has = [&](int x) {
            if (x < x0 || x >= x1) return 0;
            return (row[x] & from_bit) != 0 ? 1 : 0;
        };
        int count = 0;
        for (int x = x0 - r; x <= x0 + r; ++x)
            count += has(x);
        for (int x = x0; x < x1; ++x) {
            out[x] = static_cast<unsigned char>(erode ? count == full : count > 0);
            count += has(x + r + 1) - has(x - r);
        }
    }
    int* const counts = column_counts_.data();
    const auto has = [&](int x, int y) {
        if (y < y0 || y >= y1) return 0;
        return static_cast<int>(run[static_cast<std::ptrdiff_t>(y) * w + x]);
    };
    for (int x = x0; x < x1; ++x) {
        counts[x] = 0;
        for (int y = y0 - r; y <= y0 + r; ++y)
            counts[x] += has(x, y);
    }
    for (int y = y0; y < y1; ++y) {
        unsigned char* row = marks + static_cast<std::ptrdiff_t>(y) * w;
        for (int x = x0; x < x1; ++x) {
            if (erode ? counts[x] == full : counts[x] > 0)
                row[x] = static_cast<unsigned char>(row[x] | to_bit);
            counts[x] += has(x, y + r + 1) - has(x, y - r);
        }
    }
}

// A gap in the outline lets the fill run out into the background through a neck: the region's
// core (its pixels at least neck_radius from its outside) falls into pieces there, while a
// finger or the channel through the gap has no core at all. The piece of core nearest the
// inner point is the target's; the region keeps the pixels within neck_radius of it, and the
// pixels joined to those without passing within neck_radius of another piece: a finger stays,
// what widens beyond the neck goes. Runs on queue_'s first queued_ pixels (the inside) and
// leaves the kept ones there, in filled_ too.
void RasterEstimator::cut_necks(cv::Point2f inner) noexcept {
    const int r = settings_.neck_radius;
    if (r <= 0 || queued_ == 0) return;
    const int w = width_;
    cv::Point* const queue = queue_.data();
    int x0 = w;
    int y0 = height_;
    int x1 = 0;
    int y1 = 0;
    for (std::size_t i = 0; i < queued_; ++i) {
        x0 = std::min(x0, queue[i].x);
        y0 = std::min(y0, queue[i].y);
        x1 = std::max(x1, queue[i].x + 1);
        y1 = std::max(y1, queue[i].y + 1);
    }
    // A region crossing the border is an arm or a body coming in: its wrist is such a neck, and
    // the piece nearest the inner point may be the forearm. keep_extremity() takes its far end.
    if (x0 == 0 || y0 == 0 || x1 == w || y1 == height_) return;
    // The box grown by the dilation's reach; marks_ is clear outside the last box used.
    const int bx0 = std::max(0, x0 - r);
    const int by0 = std::max(0, y0 - r);
    const int bx1 = std::min(w, x1 + r);
    const int by1 = std::min(height_, y1 + r);
    unsigned char* const marks = marks_.data();
    for (int y = by0; y < by1; ++y)
        std::fill_n(marks + static_cast<std::ptrdiff_t>(y) * w + bx0, bx1 - bx0, 0);
    for (std::size_t i = 0; i < queued_; ++i)
        marks[static_cast<std::ptrdiff_t>(queue[i].y) * w + queue[i].x] = in_region;
    morph(in_region, in_core, true, r, x0, y0, x1, y1);
    // The core's pieces (8-connected), as runs along the rows joined by union-find: a few
    // instructions a pixel of the box, where most regions have one piece and stop here.
    Run* const runs = runs_.data();
    std::size_t count = 0;
    std::size_t above = 0;  // the previous row's runs: [above, row_start)
    for (int y = y0; y < y1; ++y) {
        const unsigned char* row = marks + static_cast<std::ptrdiff_t>(y) * w;
        const std::size_t row_start = count;
        for (int x = x0; x < x1;) {
            if ((row[x] & in_core) == 0) {
                ++x;
                continue;
            }
            const int begin = x;
            while (x < x1 && (row[x] & in_core) != 0)
                ++x;
            runs[count] = {y, begin, x, count};
            for (std::size_t k = above; k < row_start; ++k) {
                if (runs[k].begin <= x && runs[k].end >= begin) unite(k, count);
            }
            ++count;
        }
        above = row_start;
    }
    // The piece nearest the inner point is the target's.
    std::size_t pieces = 0;
    std::size_t main = count;
    float best = std::numeric_limits<float>::max();
    for (std::size_t k = 0; k < count; ++k) {
        if (root(k) == k) ++pieces;
        const float nearest_x = std::clamp(inner.x, static_cast<float>(runs[k].begin),
                                           static_cast<float>(runs[k].end - 1));
        const float dx = nearest_x - inner.x;
        const float dy = static_cast<float>(runs[k].y) - inner.y;
        if (dx * dx + dy * dy < best) {
            best = dx * dx + dy * dy;
            main = k;
        }
    }
    if (pieces <= 1) {
        clear_marks(bx0, by0, bx1, by1);
        return;
    }
    main = root(main);
    for (std::size_t k = 0; k < count; ++k) {
        const unsigned char bit = root(k) == main ? near_main : near_other;
        unsigned char* row = marks + static_cast<std::ptrdiff_t>(runs[k].y) * w;
        for (int x = runs[k].begin; x < runs[k].end; ++x)
            row[x] = static_cast<unsigned char>(row[x] | bit);
    }
    morph(near_main, near_main, false, r, bx0, by0, bx1, by1);
    morph(near_other, near_other, false, r, bx0, by0, bx1, by1);
    // From the main piece, through region pixels not near another piece only.
    cv::Point* const work = work_.data();
    count = 0;
    for (std::size_t i = 0; i < queued_; ++i) {
        const cv::Point p = queue[i];
        unsigned char& m = marks[static_cast<std::ptrdiff_t>(p.y) * w + p.x];
        if ((m & near_main) != 0) {
            m = static_cast<unsigned char>(m | in_core);  // in_core now: kept
            work[count++] = p;
        } else {
            m = static_cast<unsigned char>(m & ~in_core);
        }
    }
    for (std::size_t head = 0; head < count; ++head) {
        const cv::Point p = work[head];
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if ((dx != 0) == (dy != 0)) continue;  // four neighbours, as the fill
                const int x = p.x + dx;
                const int y = p.y + dy;
                if (x < x0 || y < y0 || x >= x1 || y >= y1) continue;
                unsigned char& m = marks[static_cast<std::ptrdiff_t>(y) * w + x];
                if ((m & in_region) == 0 || (m & in_core) != 0 || (m & near_other) != 0) continue;
                m = static_cast<unsigned char>(m | in_core);
                work[count++] = {x, y};
            }
        }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < queued_; ++i) {
        const cv::Point p = queue[i];
        const std::ptrdiff_t index = static_cast<std::ptrdiff_t>(p.y) * w + p.x;
        if ((marks[index] & in_core) != 0) {
            queue[kept++] = p;
        } else {
            filled_[static_cast<std::size_t>(index)] = 0;
        }
    }
    queued_ = kept;
    clear_marks(bx0, by0, bx1, by1);
}

std::size_t RasterEstimator::root(std::size_t run) noexcept {
    while (runs_[run].parent != run) {
        runs_[run].parent = runs_[runs_[run].parent].parent;  // path halving
        run = runs_[run].parent;
    }
    return run;
}

void RasterEstimator::unite(std::size_t a, std::size_t b) noexcept {
    const std::size_t ra = root(a);
    const std::size_t rb = root(b);
    if (ra < rb) {
        runs_[rb].parent = ra;
    } else {
        runs_[ra].parent = rb;
    }
}

void RasterEstimator::clear_marks(int x0, int y0, int x1, int y1) noexcept {
    for (int y = y0; y < y1; ++y)
        std::fill_n(marks_.data() + static_cast<std::ptrdiff_t>(y) * width_ + x0, x1 - x0, 0);
}

}  // namespace raypoint::core::detail
