#include "raypoint/core/preprocess.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::core {
namespace {

// The radius setting is in pixels of a 640-wide frame (see settings.hpp).
constexpr double reference_width = 640.0;

// Working pixel i of n covers input pixels [i*N/n, (i+1)*N/n); its centre, rounded.
int working_to_input(int index, int working_size, int input_size) noexcept {
    const double centre = (index + 0.5) * input_size / working_size - 0.5;
    return static_cast<int>(std::lround(centre));
}

// |a - b| byte by byte; the unsigned form vectorizes.
void absolute_difference(const std::uint8_t* __restrict a, const std::uint8_t* __restrict b,
                         std::uint8_t* __restrict out, int length) noexcept {
    for (int i = 0; i < length; ++i)
        out[i] = static_cast<std::uint8_t>(std::max(a[i], b[i]) - std::min(a[i], b[i]));
}

}  // namespace

namespace {

using PartialHistograms = std::array<std::array<int, 256>, 4>;

// Four interleaved histograms: a still scene puts nearly every pixel in one bin, and
// incrementing one counter back to back waits for each previous increment.
void count(PartialHistograms& bins, const std::uint8_t* values, int length) noexcept {
    int x = 0;
    for (; x + 4 <= length; x += 4) {
        ++bins[0][values[x]];
        ++bins[1][values[x + 1]];
        ++bins[2][values[x + 2]];
        ++bins[3][values[x + 3]];
    }
    for (; x < length; ++x)
        ++bins[0][values[x]];
}

// count() of values[0], values[3], ... values[3 * (length - 1)].
void count_every_third(PartialHistograms& bins, const std::uint8_t* values, int length) noexcept {
    int x = 0;
    for (; x + 4 <= length; x += 4) {
        ++bins[0][values[3 * x]];
        ++bins[1][values[3 * x + 3]];
        ++bins[2][values[3 * x + 6]];
        ++bins[3][values[3 * x + 9]];
    }
    for (; x < length; ++x)
        ++bins[0][values[3 * x]];
}

std::array<int, 256> total(const PartialHistograms& bins) noexcept {
    std::array<int, 256> histogram{};
    for (int value = 0; value < 256; ++value) {
        histogram[value] = bins[0][value] + bins[1][value] + bins[2][value] + bins[3][value];
    }
    return histogram;
}

int offset_of(const std::array<int, 256>& histogram, int minima) noexcept {
    int distinct = 0;
    int largest = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (histogram[value] == 0) continue;
        ++distinct;
        largest = value;
    }
    return largest;
}

// The sum of max(0, value - offset) over the pixels the histogram counted; exact (an integer
// sum, at most 19,200 x 255 at the working size).
double compensated_sum(const std::array<int, 256>& histogram, int offset) noexcept {
    std::int64_t sum = 0;
    for (int value = offset + 1; value < 256; ++value)
        sum += static_cast<std::int64_t>(histogram[value]) * (value - offset);
    return static_cast<double>(sum);
}

}  // namespace

int brightness_offset(const cv::Mat& difference, int minima) noexcept {
    PartialHistograms bins{};
    for (int y = 0; y < difference.rows; ++y)
        count(bins, difference.ptr<std::uint8_t>(y), difference.cols);
    return offset_of(total(bins), minima);
}

Preprocessor::Preprocessor(const PreprocessSettings& settings, InstructionSet instructions)
    : settings_(settings), instructions_(instructions) {
    const cv::Size size(settings.work_width, settings.work_height);
    for (int i = 0; i < 2; ++i) {
        color_[i].create(size, CV_8UC3);
        color_[i].setTo(cv::Scalar::all(0));
        gray_[i].create(size, CV_8U);
        gray_[i].setTo(cv::Scalar::all(0));
    }
    squared_channels_.resize(static_cast<std::size_t>(settings.work_width) * 3);
    planes_.create(settings.work_height * 3, settings.work_width, CV_8U);
    magnitude_.create(size, CV_8U);
    edges_.create(size, CV_8U);
    difference_.create(size, CV_8U);
    channel_row_.resize(static_cast<std::size_t>(settings.work_width) * 6);
    magnitude_.setTo(cv::Scalar::all(0));
    edges_.setTo(cv::Scalar::all(0));
    difference_.setTo(cv::Scalar::all(0));
}

void Preprocessor::prepare(const FrameView& frame) {
    input_width_ = frame.width;
    input_height_ = frame.height;
    input_format_ = frame.format;
    processed_ = 0;  // a new geometry has no comparable previous frame
    const auto& taps = poisson_disk_taps();
    const double radius = settings_.filter_radius * frame.width / reference_width;
    tap_columns_.assign(taps.size(), std::vector<int>(settings_.work_width));
    tap_rows_.assign(taps.size(), std::vector<int>(settings_.work_height));
    tap_dx_.assign(taps.size(), 0);
    tap_row_pointers_.assign(taps.size(), nullptr);
    centre_columns_.resize(static_cast<std::size_t>(settings_.work_width));
    int reach = 0;
    for (std::size_t t = 0; t < taps.size(); ++t) {
        const int dx = static_cast<int>(std::lround(taps[t].x * radius));
        const int dy = static_cast<int>(std::lround(taps[t].y * radius));
        tap_dx_[t] = dx;
        reach = std::max(reach, std::abs(dx));
        for (int x = 0; x < settings_.work_width; ++x) {
            const int column = working_to_input(x, settings_.work_width, frame.width) + dx;
            tap_columns_[t][x] = std::clamp(column, 0, frame.width - 1);
        }
        for (int y = 0; y < settings_.work_height; ++y) {
            const int row = working_to_input(y, settings_.work_height, frame.height) + dy;
            tap_rows_[t][y] = std::clamp(row, 0, frame.height - 1);
        }
    }
    last_tap_row_.assign(static_cast<std::size_t>(settings_.work_height), 0);
    for (int y = 0; y < settings_.work_height; ++y) {
        for (std::size_t t = 0; t < taps.size(); ++t) {
            last_tap_row_[y] = std::max(last_tap_row_[y], tap_rows_[t][y]);
        }
    }
    interior_begin_ = settings_.work_width;
    interior_end_ = 0;
    for (int x = 0; x < settings_.work_width; ++x) {
        const int centre = working_to_input(x, settings_.work_width, frame.width);
        centre_columns_[x] = centre;
        // YUYV reads the pair of a column, one past it at most.
        if (centre - reach - 1 >= 0 && centre + reach + 1 < frame.width) {
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
    tap_odd_.assign(taps.size(), 0);
    tap_shift_bytes_.assign(taps.size(), 0);
    centre_bytes_.resize(static_cast<std::size_t>(settings_.work_width));
    const bool bgr = frame.format == PixelFormat::bgr;
    for (std::size_t t = 0; t < taps.size(); ++t) {
        tap_odd_[t] = ((parity + tap_dx_[t]) & 1) != 0 ? 1 : 0;
        tap_shift_bytes_[t] = bgr ? tap_dx_[t] * 3 : ((parity + tap_dx_[t]) & ~1) * 2;
    }
    for (int x = 0; x < settings_.work_width; ++x)
        centre_bytes_[x] = bgr ? centre_columns_[x] * 3 : (centre_columns_[x] & ~1) * 2;
}

bool Preprocessor::process(const FrameView& frame) noexcept {
    if (!filter(frame)) return false;
    compute_edges();
    compute_difference();
    return true;
}

bool Preprocessor::filter(const FrameView& frame) noexcept {
    const int bytes_per_pixel = frame.format == PixelFormat::bgr ? 3 : 2;
    if (frame.data == nullptr || frame.width < settings_.work_width ||
        frame.height < settings_.work_height || frame.stride < frame.width * bytes_per_pixel ||
        (frame.format == PixelFormat::yuyv && frame.width % 2 != 0)) {
        return false;
    }
    if (frame.width != input_width_ || frame.height != input_height_ ||
        frame.format != input_format_) {
        try {
            prepare(frame);
        } catch (...) {  // out of memory while setting up a new geometry: skip the frame
            input_width_ = 0;
            return false;
        }
    }
    current_ = 1 - current_;
    switch (frame.format) {
        case PixelFormat::bgr:
            filter_bgr(frame);
            break;
        case PixelFormat::yuyv:
            filter_yuyv(frame);
            break;
    }
    ++processed_;
    return true;
}

// The difference image is the grey one (paper 4.1): its centre of mass picks the target, and
// the target is what contrasts most. The movement value that starts a search may come from
// the largest per-channel difference instead, which also sees a skin hand move over a wall of
// its own brightness.
// One pass over the rows: the grey difference image and its histogram, and the per-channel
// difference's histogram; the offsets and the movement sums come from the histograms, so only
// the grey image is compensated in place.
void Preprocessor::compute_difference() noexcept {
    if (!has_previous()) {
        difference_.setTo(cv::Scalar::all(0));
        movement_ = 0.0;
        offset_ = 0;
        return;
    }
    const bool channels = settings_.movement_source == EdgeSource::max_channel;
    const int width = difference_.cols;
    std::uint8_t* const channel_row = channel_row_.data();  // 3 * width, then 3 * width
    std::uint8_t* const strongest = channel_row + 3 * width;
    grey_bins_ = {};
    channel_bins_ = {};
    for (int y = 0; y < difference_.rows; ++y) {
        absolute_difference(gray_[current_].ptr<std::uint8_t>(y),
                            gray_[1 - current_].ptr<std::uint8_t>(y),
                            difference_.ptr<std::uint8_t>(y), width);
        count(grey_bins_, difference_.ptr<std::uint8_t>(y), width);
        if (!channels) continue;
        absolute_difference(color_[current_].ptr<std::uint8_t>(y),
                            color_[1 - current_].ptr<std::uint8_t>(y), channel_row, 3 * width);
        // The max of each byte and the next two, contiguous so it vectorizes; pixel x's is at 3x.
        for (int i = 0; i + 2 < 3 * width; ++i)
            strongest[i] = std::max({channel_row[i], channel_row[i + 1], channel_row[i + 2]});
        count_every_third(channel_bins_, strongest, width);
    }
    const std::array<int, 256> grey = total(grey_bins_);
    offset_ = offset_of(grey, settings_.compensation_minima);
    movement_ = compensated_sum(grey, offset_);
    if (channels) {
        const std::array<int, 256> channel = total(channel_bins_);
        movement_ = compensated_sum(channel, offset_of(channel, settings_.compensation_minima));
    }
    const auto offset = static_cast<std::uint8_t>(offset_);
    for (int y = 0; y < difference_.rows; ++y) {
        std::uint8_t* row = difference_.ptr<std::uint8_t>(y);
        for (int x = 0; x < width; ++x)
            row[x] = static_cast<std::uint8_t>(row[x] > offset ? row[x] - offset : 0);
    }
}

}  // namespace raypoint::core
