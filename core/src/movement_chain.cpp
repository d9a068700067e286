// SPDX-License-Identifier: MIT
#include "movement_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace raypoint::core::detail {

namespace {

// Grey levels, working pixels and seconds for a 160x120 working frame, measured on the real
// waving hand and the rendered clips (docs/accuracy.md, "The movement's chain").
constexpr int difference_floor = 20;    // a strongest difference under this: nothing moved
constexpr double strong_share = 0.3;    // the mean shift weighs pixels at this share of it
constexpr int half_window = 14;         // the mean shift's window: 29x29 working pixels
constexpr int foreground_level = 30;    // a pixel this far from the scene shows the target
constexpr double moved_share = 0.15;    // ... and moved: this share of the strongest difference
constexpr double scene_seconds = 0.78;  // the running average's time constant (0.05 at 25 fps)
constexpr int min_pixels = 3;           // fewer leading pixels: the mean shift's point stands
// share_near counts differences at this share of the strongest: a camera's noise and JPEG blocks
// spread faint difference over the whole frame, which would leave any target a small share.
constexpr double share_floor = 0.15;

int largest_channel_difference(const cv::Vec3b& a, const cv::Vec3b& b) noexcept {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

float largest_channel_distance(const cv::Vec3b& a, const cv::Vec3f& b) noexcept {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

void MovementChain::reset() noexcept {
    frames_ = 0;
    strongest_ = 0;
    point_.reset();
    led_at_.reset();
}

void MovementChain::update(const cv::Mat& color, Timestamp timestamp) noexcept {
    if (color.empty() || color.type() != CV_8UC3) {
        reset();
        return;
    }
    if (frames_ > 0 && current_.size() != color.size()) reset();
    try {
        // Three frames' buffers turn round: no allocation once each has the frame's size.
        std::swap(before_previous_, previous_);
        std::swap(previous_, current_);
        color.copyTo(current_);
        difference_.create(color.size(), CV_8U);
        if (frames_ >= 1) {
            if (frames_ == 1) {
                previous_.convertTo(scene_, CV_32FC3);
            } else {
                const double seconds = static_cast<double>(timestamp - frame_time_) / 1e6;
                const double weight = 1.0 - std::exp(-std::max(0.0, seconds) / scene_seconds);
                cv::accumulateWeighted(previous_, scene_, weight);
            }
        }
    } catch (...) {
        reset();
        return;
    }
    frame_time_ = timestamp;
    frames_ = std::min(frames_ + 1, 3);
    strongest_ = 0;
    total_ = 0.0;
    if (frames_ < 2) return;
    try {
        // OpenCV's vector kernels on whole images, into buffers that keep their size: the
        // largest channel's absolute difference, its maximum, and its sum over the pixels
        // share_near counts.
        cv::absdiff(current_, previous_, channels_);
        cv::split(channels_, planes_.data());
        cv::max(planes_[0], planes_[1], difference_);
        cv::max(difference_, planes_[2], difference_);
        double strongest = 0.0;
        cv::minMaxLoc(difference_, nullptr, &strongest);
        strongest_ = static_cast<int>(strongest);
        // Whole grey levels: d >= floor is d > ceil(floor) - 1.
        const double below = std::ceil(share_floor * strongest_) - 1.0;
        cv::threshold(difference_, counted_, below, 0.0, cv::THRESH_TOZERO);
        total_ = cv::sum(counted_)[0];
    } catch (...) {
        reset();
    }
}

std::optional<cv::Point2f> MovementChain::strong_centre(cv::Rect box) const noexcept {
    const double strong = strong_share * strongest_;
    double sum = 0.0;
    double sx = 0.0;
    double sy = 0.0;
    for (int row = box.y; row < box.y + box.height; ++row) {
        const auto* d = difference_.ptr<std::uint8_t>(row);
        for (int col = box.x; col < box.x + box.width; ++col) {
            if (d[col] < strong) continue;
            sum += d[col];
            sx += d[col] * col;
            sy += d[col] * row;
        }
    }
    if (sum <= 0.0) return std::nullopt;
    return cv::Point2f(static_cast<float>(sx / sum), static_cast<float>(sy / sum));
}

std::optional<cv::Point2f> MovementChain::shift(cv::Point2f at) const noexcept {
    const cv::Rect frame(0, 0, difference_.cols, difference_.rows);
    for (int iteration = 0; iteration < 10; ++iteration) {
        const cv::Point corner(static_cast<int>(at.x - half_window),
                               static_cast<int>(at.y - half_window));
        const cv::Rect window =
            cv::Rect(corner, cv::Size(2 * half_window + 1, 2 * half_window + 1)) & frame;
        const auto centre = strong_centre(window);
        if (!centre) return iteration == 0 ? std::nullopt : std::optional<cv::Point2f>(at);
        const bool settled = std::abs(centre->x - at.x) < 0.2F && std::abs(centre->y - at.y) < 0.2F;
        at = *centre;
        if (settled) break;
    }
    return at;
}

std::optional<cv::Point2f> MovementChain::locate(cv::Point2f start) const noexcept {
    if (frames_ < 2 || strongest_ < difference_floor) return std::nullopt;
    const auto centre = shift(start);
    if (!centre) return std::nullopt;
    const int x0 = std::max(0, static_cast<int>(centre->x - half_window));
    const int x1 = std::min(current_.cols, static_cast<int>(centre->x + half_window + 1));
    const int y0 = std::max(0, static_cast<int>(centre->y - half_window));
    const int y1 = std::min(current_.rows, static_cast<int>(centre->y + half_window + 1));
    const double moved = moved_share * strongest_;
    int count = 0;
    double sx = 0.0;
    double sy = 0.0;
    for (int row = y0; row < y1; ++row) {
        const auto* now = current_.ptr<cv::Vec3b>(row);
        const auto* before = previous_.ptr<cv::Vec3b>(row);
        const auto* scene = scene_.ptr<cv::Vec3f>(row);
        const auto* one = difference_.ptr<std::uint8_t>(row);
        const auto* two_back = frames_ >= 3 ? before_previous_.ptr<cv::Vec3b>(row) : nullptr;
        for (int col = x0; col < x1; ++col) {
            // Moved in the last two frames: against the frame before, or the one before that.
            if (one[col] < moved && (two_back == nullptr ||
                                     largest_channel_difference(now[col], two_back[col]) < moved))
                continue;
            const float here = largest_channel_distance(now[col], scene[col]);
            if (here <= foreground_level ||
                here <= largest_channel_distance(before[col], scene[col]))
                continue;
            ++count;
            sx += col;
            sy += row;
        }
    }
    if (count < min_pixels) return centre;
    return cv::Point2f(static_cast<float>(sx / count), static_cast<float>(sy / count));
}

std::optional<cv::Point2f> MovementChain::follow(std::optional<cv::Point2f> target) noexcept {
    if (frames_ < 2 || strongest_ < difference_floor) return point_;  // nothing moved: it stays
    // Only from its own point once it has one: a hand that rests while someone passes behind it
    // is not handed to the passer's movement. Never from the whole frame's movement before the
    // tracker had a target: under a flickering light that is everywhere and nowhere.
    const std::optional<cv::Point2f> from = point_ ? point_ : target;
    if (!from) return std::nullopt;
    if (const auto led = locate(*from)) {
        point_ = led;
        led_at_ = frame_time_;
    }
    return point_;
}

double MovementChain::share_near(cv::Point2f centre, double radius) const noexcept {
    if (frames_ < 2 || total_ <= 0.0) return 1.0;
    const double r2 = radius * radius;
    const int x0 = std::max(0, static_cast<int>(std::floor(centre.x - radius)));
    const int x1 = std::min(difference_.cols - 1, static_cast<int>(std::ceil(centre.x + radius)));
    const int y0 = std::max(0, static_cast<int>(std::floor(centre.y - radius)));
    const int y1 = std::min(difference_.rows - 1, static_cast<int>(std::ceil(centre.y + radius)));
    const double floor = share_floor * strongest_;
    double sum = 0.0;
    for (int y = y0; y <= y1; ++y) {
        const auto* d = difference_.ptr<std::uint8_t>(y);
        for (int x = x0; x <= x1; ++x) {
            const double dx = static_cast<double>(x) - centre.x;
            const double dy = static_cast<double>(y) - centre.y;
            if (dx * dx + dy * dy <= r2 && d[x] >= floor) sum += d[x];
        }
    }
    return sum / total_;
}

}  // namespace raypoint::core::detail
