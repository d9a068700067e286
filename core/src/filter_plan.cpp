// SPDX-License-Identifier: MIT
// The Poisson-disk filter's plan (paper 4.1): tap positions per working pixel, clamped to the
// frame, and the interior where the vector kernels need no clamping.

#include "raypoint/core/filter_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace raypoint::core {
namespace {

// The radius setting is in pixels of a 640-wide frame (see settings.hpp).
constexpr double reference_width = 640.0;

// Working pixel i of n covers input pixels [i*N/n, (i+1)*N/n); its centre, rounded.
int working_to_input(int index, int working_size, int input_size) noexcept {
    const double centre = (index + 0.5) * input_size / working_size - 0.5;
    return static_cast<int>(std::lround(centre));
}

}  // namespace

FilterPlan::FilterPlan(cv::Size working, double filter_radius)
    : working_(working), filter_radius_(filter_radius) {}

void FilterPlan::build(int input_width, int input_height, PixelFormat format) {
    input_width_ = 0;  // matches no frame until the plan is complete
    const auto& offsets = poisson_disk_taps();
    const int width = working_.width;
    const int height = working_.height;
    const double radius = filter_radius_ * input_width / reference_width;
    centre_columns_.resize(static_cast<std::size_t>(width));
    int reach = 0;
    for (std::size_t t = 0; t < taps_.size(); ++t) {
        FilterTap& tap = taps_[t];
        tap.dx = static_cast<int>(std::lround(offsets[t].x * radius));
        const int dy = static_cast<int>(std::lround(offsets[t].y * radius));
        reach = std::max(reach, std::abs(tap.dx));
        tap.columns.resize(static_cast<std::size_t>(width));
        tap.rows.resize(static_cast<std::size_t>(height));
        for (int x = 0; x < width; ++x) {
            const int column = working_to_input(x, width, input_width) + tap.dx;
            tap.columns[x] = std::clamp(column, 0, input_width - 1);
        }
        for (int y = 0; y < height; ++y) {
            const int row = working_to_input(y, height, input_height) + dy;
            tap.rows[y] = std::clamp(row, 0, input_height - 1);
        }
    }
    last_tap_rows_.assign(static_cast<std::size_t>(height), 0);
    for (int y = 0; y < height; ++y) {
        for (const FilterTap& tap : taps_)
            last_tap_rows_[y] = std::max(last_tap_rows_[y], tap.rows[y]);
    }
    interior_begin_ = width;
    interior_end_ = 0;
    for (int x = 0; x < width; ++x) {
        const int centre = working_to_input(x, width, input_width);
        centre_columns_[x] = centre;
        // YUYV reads the pair of a column, one past it at most.
        if (centre - reach - 1 >= 0 && centre + reach + 1 < input_width) {
            interior_begin_ = std::min(interior_begin_, x);
            interior_end_ = std::max(interior_end_, x + 1);
        }
    }
    if (interior_begin_ >= interior_end_) interior_begin_ = interior_end_ = 0;
    // YUYV: with every interior centre of one parity p (even for 640, 1280, 1920 wide; odd
    // for 320), column c + dx of centre c is in the pair starting at (c - p) + ((p + dx) & ~1)
    // and its Y is the pair's second when p + dx is odd, the same for every centre.
    const int parity = interior_begin_ < interior_end_ ? centre_columns_[interior_begin_] & 1 : 0;
    uniform_parity_ = true;
    for (int x = interior_begin_; x < interior_end_; ++x) {
        if ((centre_columns_[x] & 1) != parity) uniform_parity_ = false;
    }
    const bool bgr = format == PixelFormat::bgr;
    odd_taps_ = 0;
    for (std::size_t t = 0; t < taps_.size(); ++t) {
        FilterTap& tap = taps_[t];
        tap.odd_luma = ((parity + tap.dx) & 1) != 0;
        tap.shift_bytes = bgr ? tap.dx * 3 : ((parity + tap.dx) & ~1) * 2;
        if (tap.odd_luma) odd_taps_ |= 1U << t;
    }
    centre_bytes_.resize(static_cast<std::size_t>(width));
    for (int x = 0; x < width; ++x)
        centre_bytes_[x] = bgr ? centre_columns_[x] * 3 : (centre_columns_[x] & ~1) * 2;
    centre_step_bytes_ = 0;
    if (interior_end_ - interior_begin_ >= 2) {
        centre_step_bytes_ = centre_bytes_[interior_begin_ + 1] - centre_bytes_[interior_begin_];
        for (int x = interior_begin_ + 1; x < interior_end_; ++x) {
            if (centre_bytes_[x] - centre_bytes_[x - 1] != centre_step_bytes_)
                centre_step_bytes_ = 0;
        }
    }
    int largest_shift = 0;
    for (const FilterTap& tap : taps_)
        largest_shift = std::max(largest_shift, tap.shift_bytes);
    read_limit_ = input_width * (bgr ? 3 : 2) - largest_shift;
    plan_border(input_width, bgr);
    input_width_ = input_width;
    input_height_ = input_height;
    format_ = format;
}

// The columns outside [interior_begin, interior_end), or every column where the YUYV kernels
// do not apply, four to a group. A BGR load starts at the pixel's B, or one byte before it
// where 4 bytes from B would pass the row's end; a YUYV load at the column's pair.
void FilterPlan::plan_border(int input_width, bool bgr) {
    std::vector<int> columns;
    const bool kernels = bgr || uniform_parity_;
    for (int x = 0; x < working_.width; ++x) {
        if (!kernels || x < interior_begin_ || x >= std::max(interior_end_, interior_begin_))
            columns.push_back(x);
    }
    const int row_bytes = input_width * (bgr ? 3 : 2);
    constexpr std::uint8_t zero = 0x80;  // pshufb writes 0 for a set high bit
    border_groups_.assign((columns.size() + 3) / 4, FilterBorderGroup{});
    for (std::size_t g = 0; g < border_groups_.size(); ++g) {
        FilterBorderGroup& group = border_groups_[g];
        group.count = static_cast<int>(std::min<std::size_t>(4, columns.size() - 4 * g));
        for (int k = 0; k < 4; ++k)
            group.columns[k] = columns[4 * g + std::min(k, group.count - 1)];
        for (std::size_t t = 0; t < taps_.size(); ++t) {
            FilterBorderGroup::Tap& tap = group.taps[t];
            tap.select.fill(zero);
            for (int k = 0; k < 4; ++k) {
                const int column = taps_[t].columns[group.columns[k]];
                std::array<int, 3> bytes{};  // of the three values, within the 4 loaded
                if (bgr) {
                    const bool back = column * 3 + 4 > row_bytes && column > 0;
                    tap.loads[k] = column * 3 - (back ? 1 : 0);
                    bytes = back ? std::array<int, 3>{1, 2, 3} : std::array<int, 3>{0, 1, 2};
                } else {
                    tap.loads[k] = (column & ~1) * 2;
                    bytes = {(column & 1) * 2, 1, 3};
                }
                for (int value = 0; value < 3; ++value)
                    tap.select[k * 8 + value * 2] = static_cast<std::uint8_t>(k * 4 + bytes[value]);
            }
        }
    }
}

}  // namespace raypoint::core
