#include "raypoint/core/preprocess.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

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

std::uint8_t clamp_byte(int value) noexcept {
    return static_cast<std::uint8_t>(std::clamp(value, 0, 255));
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

Preprocessor::Preprocessor(const PreprocessSettings& settings) : settings_(settings) {
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
    for (std::size_t t = 0; t < taps.size(); ++t)
        tap_odd_[t] = (tap_dx_[t] & 1) != 0 ? 1 : 0;
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
    cv::cvtColor(color_[current_], gray_[current_], cv::COLOR_BGR2GRAY);
    compute_edges();
    ++processed_;
    compute_difference();
    return true;
}

// The filter is evaluated only at the working pixels' centres: filtering the whole frame and
// then subsampling gives the same values at 16x the cost for 640x480. Working pixel outside,
// taps inside, so the sums stay in registers; the interior skips the clamped column tables.
void Preprocessor::filter_bgr(const FrameView& frame) noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    cv::Mat& out = color_[current_];
    for (int y = 0; y < settings_.work_height; ++y) {
        start_row(frame, y);
        auto* target = out.ptr<std::uint8_t>(y);
        const auto store = [&](int x, unsigned b, unsigned g, unsigned r) {
            target[x * 3 + 0] = static_cast<std::uint8_t>((b + tap_count / 2) / tap_count);
            target[x * 3 + 1] = static_cast<std::uint8_t>((g + tap_count / 2) / tap_count);
            target[x * 3 + 2] = static_cast<std::uint8_t>((r + tap_count / 2) / tap_count);
        };
        const auto clamped = [&](int x) {
            unsigned b = 0, g = 0, r = 0;
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + tap_columns_[t][x] * 3;
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            store(x, b, g, r);
        };
        int x = 0;
        for (; x < interior_begin_; ++x)
            clamped(x);
#if defined(__SSE2__)
        // Four working pixels a step: each tap's B, G, R (and the next pixel's B, ignored) are
        // one 32-bit load widened to 16-bit lanes; 16 taps x 255 fit in 16 bits. The interior
        // has a column to spare on the right, so the 4th byte is inside the frame.
        for (unsigned t = 0; t < tap_count; ++t)
            tap_row_pointers_[t] += tap_dx_[t] * 3;
        const __m128i zero = _mm_setzero_si128();
        for (; x + 4 <= interior_end_; x += 4) {
            const int c0 = centre_columns_[x] * 3;
            const int c1 = centre_columns_[x + 1] * 3;
            const int c2 = centre_columns_[x + 2] * 3;
            const int c3 = centre_columns_[x + 3] * 3;
            __m128i low = _mm_setzero_si128();   // pixels x, x+1
            __m128i high = _mm_setzero_si128();  // pixels x+2, x+3
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* row = tap_row_pointers_[t];
                std::uint32_t p0 = 0, p1 = 0, p2 = 0, p3 = 0;
                std::memcpy(&p0, row + c0, 4);
                std::memcpy(&p1, row + c1, 4);
                std::memcpy(&p2, row + c2, 4);
                std::memcpy(&p3, row + c3, 4);
                const __m128i packed = _mm_setr_epi32(static_cast<int>(p0), static_cast<int>(p1),
                                                      static_cast<int>(p2), static_cast<int>(p3));
                low = _mm_add_epi16(low, _mm_unpacklo_epi8(packed, zero));
                high = _mm_add_epi16(high, _mm_unpackhi_epi8(packed, zero));
            }
            alignas(16) std::uint16_t lanes[16];
            _mm_store_si128(reinterpret_cast<__m128i*>(lanes), low);
            _mm_store_si128(reinterpret_cast<__m128i*>(lanes + 8), high);
            for (int k = 0; k < 4; ++k)
                store(x + k, lanes[4 * k], lanes[4 * k + 1], lanes[4 * k + 2]);
        }
        for (unsigned t = 0; t < tap_count; ++t)
            tap_row_pointers_[t] -= tap_dx_[t] * 3;
#endif
        for (; x < interior_end_; ++x) {
            const int centre = centre_columns_[x];
            unsigned b = 0, g = 0, r = 0;
            for (unsigned t = 0; t < tap_count; ++t) {
                const std::uint8_t* pixel = tap_row_pointers_[t] + (centre + tap_dx_[t]) * 3;
                b += pixel[0];
                g += pixel[1];
                r += pixel[2];
            }
            store(x, b, g, r);
        }
        for (x = std::max(interior_end_, interior_begin_); x < settings_.work_width; ++x) {
            clamped(x);
        }
    }
}

// Points each tap at its input row for working row y, and fetches the rows of the next.
void Preprocessor::start_row(const FrameView& frame, int y) noexcept {
    for (std::size_t t = 0; t < tap_row_pointers_.size(); ++t) {
        tap_row_pointers_[t] =
            frame.data + static_cast<std::ptrdiff_t>(tap_rows_[t][y]) * frame.stride;
    }
    prefetch_rows(frame, y + 1);
}

// A camera frame arrives cold in memory; the taps read 16 rows at a time, too many streams
// for the hardware prefetcher, so the rows the next working row adds are fetched ahead.
void Preprocessor::prefetch_rows(const FrameView& frame, int next_y) const noexcept {
#if defined(__SSE2__)
    if (next_y >= settings_.work_height) return;
    const int first = last_tap_row_[next_y - 1] + 1;
    const int last = last_tap_row_[next_y];
    const int bytes = frame.width * (frame.format == PixelFormat::bgr ? 3 : 2);
    for (int row = first; row <= last; ++row) {
        const std::uint8_t* start = frame.data + static_cast<std::ptrdiff_t>(row) * frame.stride;
        for (int offset = 0; offset < bytes; offset += 64) {
            _mm_prefetch(reinterpret_cast<const char*>(start + offset), _MM_HINT_T0);
        }
    }
#else
    (void)frame;
    (void)next_y;
#endif
}

// YUYV: Y from the pixel itself, U and V from its pair; averaged as YUV, then converted to BGR
// with BT.601 limited range, the usual meaning of V4L2_PIX_FMT_YUYV from webcams.
void Preprocessor::filter_yuyv(const FrameView& frame) noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    cv::Mat& out = color_[current_];
    for (int y = 0; y < settings_.work_height; ++y) {
        start_row(frame, y);
        auto* target = out.ptr<std::uint8_t>(y);
        const auto store = [&](int x, unsigned sum_y, unsigned sum_u, unsigned sum_v) {
            const int luma = static_cast<int>((sum_y + tap_count / 2) / tap_count) - 16;
            const int u = static_cast<int>((sum_u + tap_count / 2) / tap_count) - 128;
            const int v = static_cast<int>((sum_v + tap_count / 2) / tap_count) - 128;
            const int scaled = 298 * luma + 128;
            target[x * 3 + 0] = clamp_byte((scaled + 516 * u) >> 8);
            target[x * 3 + 1] = clamp_byte((scaled - 100 * u - 208 * v) >> 8);
            target[x * 3 + 2] = clamp_byte((scaled + 409 * v) >> 8);
        };
        int x = 0;
#if defined(__SSE2__)
        // With an even centre parity (integer scales: 640, 1280, 1920 wide to 160) a tap's Y is
        // the first or the second of its pair for every working pixel alike, so four pixels a
        // step sum whole Y0 U Y1 V groups, split by the tap's parity, and pick the Y at the end.
        if (uniform_parity_) {
            for (; x < interior_begin_; ++x)
                store_yuyv_clamped(x, store);
            const __m128i zero = _mm_setzero_si128();
            for (; x + 4 <= interior_end_; x += 4) {
                __m128i even_low = zero, even_high = zero, odd_low = zero, odd_high = zero;
                for (unsigned t = 0; t < tap_count; ++t) {
                    const std::uint8_t* row = tap_row_pointers_[t];
                    std::uint32_t p[4];
                    for (int k = 0; k < 4; ++k) {
                        std::memcpy(&p[k], row + ((centre_columns_[x + k] + tap_dx_[t]) & ~1) * 2,
                                    4);
                    }
                    const __m128i packed =
                        _mm_setr_epi32(static_cast<int>(p[0]), static_cast<int>(p[1]),
                                       static_cast<int>(p[2]), static_cast<int>(p[3]));
                    const __m128i low = _mm_unpacklo_epi8(packed, zero);
                    const __m128i high = _mm_unpackhi_epi8(packed, zero);
                    if (tap_odd_[t] != 0) {
                        odd_low = _mm_add_epi16(odd_low, low);
                        odd_high = _mm_add_epi16(odd_high, high);
                    } else {
                        even_low = _mm_add_epi16(even_low, low);
                        even_high = _mm_add_epi16(even_high, high);
                    }
                }
                alignas(16) std::uint16_t even[16];
                alignas(16) std::uint16_t odd[16];
                _mm_store_si128(reinterpret_cast<__m128i*>(even), even_low);
                _mm_store_si128(reinterpret_cast<__m128i*>(even + 8), even_high);
                _mm_store_si128(reinterpret_cast<__m128i*>(odd), odd_low);
                _mm_store_si128(reinterpret_cast<__m128i*>(odd + 8), odd_high);
                for (int k = 0; k < 4; ++k) {
                    const int lane = 4 * k;  // Y0 U Y1 V of pixel k
                    store(x + k, even[lane] + odd[lane + 2], even[lane + 1] + odd[lane + 1],
                          even[lane + 3] + odd[lane + 3]);
                }
            }
        }
#endif
        for (; x < settings_.work_width; ++x)
            store_yuyv_clamped(x, store);
    }
}

// One working pixel of a YUYV frame through the clamped column tables (borders, odd scales).
template <typename Store>
void Preprocessor::store_yuyv_clamped(int x, Store& store) const noexcept {
    const auto tap_count = static_cast<unsigned>(tap_columns_.size());
    const bool interior = x >= interior_begin_ && x < interior_end_;
    unsigned sum_y = 0, sum_u = 0, sum_v = 0;
    for (unsigned t = 0; t < tap_count; ++t) {
        const int column = interior ? centre_columns_[x] + tap_dx_[t] : tap_columns_[t][x];
        const std::uint8_t* pair = tap_row_pointers_[t] + (column & ~1) * 2;
        sum_y += pair[(column & 1) * 2];
        sum_u += pair[1];
        sum_v += pair[3];
    }
    store(x, sum_y, sum_u, sum_v);
}

// Sobel 3x3 on each channel, replicated border; the magnitude is the L2 norm, saturated to 8
// bits as in a grey edge image. EdgeSource::luma uses the grey image's gradient (paper 4.1);
// max_channel the strongest channel's, which keeps a skin hand's outline over a background of
// equal brightness. Written out rather than cv::Sobel, which allocates its filter every call.
void Preprocessor::compute_edges() noexcept {
    switch (settings_.edge_source) {
        case EdgeSource::luma:
            compute_edges_of<1>(gray_[current_]);
            break;
        case EdgeSource::max_channel:
            compute_edges_of<3>(color_[current_]);
            break;
    }
}

// Squared gradients of one row's samples, all channels interleaved; the border columns repeat
// their neighbour. Restrict-qualified and with the channel stride a constant, so the compiler
// vectorizes it.
template <int Channels>
static void squared_gradients(const std::uint8_t* __restrict above,
                              const std::uint8_t* __restrict here,
                              const std::uint8_t* __restrict below, int* __restrict out,
                              int row_length) noexcept {
    const auto gradient = [&](int i, int left, int right) {
        const int gx = (above[right] + 2 * here[right] + below[right]) -
                       (above[left] + 2 * here[left] + below[left]);
        const int gy = (below[left] + 2 * below[i] + below[right]) -
                       (above[left] + 2 * above[i] + above[right]);
        return gx * gx + gy * gy;
    };
    for (int i = 0; i < Channels; ++i) {
        out[i] = gradient(i, i, i + Channels);
        const int last = row_length - Channels + i;
        out[last] = gradient(last, last - Channels, last);
    }
    for (int i = Channels; i < row_length - Channels; ++i) {
        const int gx = (above[i + Channels] + 2 * here[i + Channels] + below[i + Channels]) -
                       (above[i - Channels] + 2 * here[i - Channels] + below[i - Channels]);
        const int gy = (below[i - Channels] + 2 * below[i] + below[i + Channels]) -
                       (above[i - Channels] + 2 * above[i] + above[i + Channels]);
        out[i] = gx * gx + gy * gy;
    }
}

template <int Channels>
void Preprocessor::compute_edges_of(const cv::Mat& source) noexcept {
    const int width = source.cols;
    const int height = source.rows;
    const int threshold = settings_.edge_threshold;
    int* const squared = squared_channels_.data();
    float* const strongest = strongest_.data();
    for (int y = 0; y < height; ++y) {
        squared_gradients<Channels>(
            source.ptr<std::uint8_t>(std::max(y - 1, 0)), source.ptr<std::uint8_t>(y),
            source.ptr<std::uint8_t>(std::min(y + 1, height - 1)), squared, width * Channels);
        for (int x = 0; x < width; ++x) {
            int value = squared[x * Channels];
            for (int c = 1; c < Channels; ++c)
                value = std::max(value, squared[x * Channels + c]);
            strongest[x] = static_cast<float>(value);
        }
        auto* magnitude = magnitude_.ptr<std::uint8_t>(y);
        auto* edge = edges_.ptr<std::uint8_t>(y);
        for (int x = 0; x < width; ++x) {
            const int value = static_cast<int>(std::min(255.0F, std::sqrt(strongest[x])));
            magnitude[x] = static_cast<std::uint8_t>(value);
            // Edge pixels keep their magnitude: the raster estimator climbs it to the ridge.
            edge[x] = value > threshold ? static_cast<std::uint8_t>(value) : 0;
        }
    }
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
