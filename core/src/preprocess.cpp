#include "raypoint/core/preprocess.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

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

int brightness_offset(const cv::Mat& difference, int minima) noexcept {
    // Four interleaved histograms: a still scene puts nearly every pixel in one bin, and
    // incrementing one counter back to back waits for each previous increment.
    std::array<std::array<int, 256>, 4> partial{};
    for (int y = 0; y < difference.rows; ++y) {
        const std::uint8_t* row = difference.ptr<std::uint8_t>(y);
        int x = 0;
        for (; x + 4 <= difference.cols; x += 4) {
            ++partial[0][row[x]];
            ++partial[1][row[x + 1]];
            ++partial[2][row[x + 2]];
            ++partial[3][row[x + 3]];
        }
        for (; x < difference.cols; ++x)
            ++partial[0][row[x]];
    }
    std::array<int, 256> histogram{};
    for (int value = 0; value < 256; ++value) {
        histogram[value] =
            partial[0][value] + partial[1][value] + partial[2][value] + partial[3][value];
    }
    int distinct = 0;
    int largest = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (histogram[value] == 0) continue;
        ++distinct;
        largest = value;
    }
    return largest;
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
    strongest_.resize(static_cast<std::size_t>(settings.work_width));
    magnitude_.create(size, CV_8U);
    edges_.create(size, CV_8U);
    difference_.create(size, CV_8U);
    color_difference_.create(size, CV_8UC3);
    channel_difference_.create(size, CV_8U);
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
    uniform_parity_ = true;
    for (int x = interior_begin_; x < interior_end_; ++x) {
        if (centre_columns_[x] % 2 != 0) uniform_parity_ = false;
    }
    tap_odd_.assign(taps.size(), 0);
    tap_shift_bytes_.assign(taps.size(), 0);
    centre_bytes_.resize(static_cast<std::size_t>(settings_.work_width));
    const bool bgr = frame.format == PixelFormat::bgr;
    for (std::size_t t = 0; t < taps.size(); ++t) {
        tap_odd_[t] = (tap_dx_[t] & 1) != 0 ? 1 : 0;
        tap_shift_bytes_[t] = bgr ? tap_dx_[t] * 3 : (tap_dx_[t] & ~1) * 2;
    }
    for (int x = 0; x < settings_.work_width; ++x)
        centre_bytes_[x] = bgr ? centre_columns_[x] * 3 : (centre_columns_[x] & ~1) * 2;
}

bool Preprocessor::process(const FrameView& frame) noexcept {
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
    compute_edges();
    ++processed_;
    compute_difference();
    return true;
}

// Subtracts the brightness change (paper 4.1) in place and returns the sum left.
double Preprocessor::compensate(cv::Mat& difference) noexcept {
    offset_ = brightness_offset(difference, settings_.compensation_minima);
    double sum = 0.0;
    for (int y = 0; y < difference.rows; ++y) {
        auto* row = difference.ptr<std::uint8_t>(y);
        for (int x = 0; x < difference.cols; ++x) {
            const int value = std::max(0, row[x] - offset_);
            row[x] = static_cast<std::uint8_t>(value);
            sum += value;
        }
    }
    return sum;
}

// The difference image is the grey one (paper 4.1): its centre of mass picks the target, and
// the target is what contrasts most. The movement value that starts a search may come from
// the largest per-channel difference instead, which also sees a skin hand move over a wall of
// its own brightness.
void Preprocessor::compute_difference() noexcept {
    if (!has_previous()) {
        difference_.setTo(cv::Scalar::all(0));
        movement_ = 0.0;
        offset_ = 0;
        return;
    }
    switch (settings_.movement_source) {
        case EdgeSource::luma:
            break;
        case EdgeSource::max_channel:
            cv::absdiff(color_[current_], color_[1 - current_], color_difference_);
            for (int y = 0; y < channel_difference_.rows; ++y) {
                const auto* in = color_difference_.ptr<std::uint8_t>(y);
                auto* out = channel_difference_.ptr<std::uint8_t>(y);
                for (int x = 0; x < channel_difference_.cols; ++x) {
                    out[x] = std::max({in[3 * x], in[3 * x + 1], in[3 * x + 2]});
                }
            }
            movement_ = compensate(channel_difference_);
            break;
    }
    cv::absdiff(gray_[current_], gray_[1 - current_], difference_);
    const double luma_movement = compensate(difference_);
    if (settings_.movement_source == EdgeSource::luma) movement_ = luma_movement;
}

}  // namespace raypoint::core
