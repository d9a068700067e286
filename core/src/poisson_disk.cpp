// SPDX-License-Identifier: MIT
// The Poisson-disk filter's tap offsets (paper 4.1).

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raypoint/core/poisson_disk.hpp"

namespace raypoint::core {
namespace {

// A tiny fixed generator so the tap set is the same on every platform and standard library
// (std::uniform_real_distribution is implementation-defined).
class SplitMix {
  public:
    double next_unit() noexcept {
        state_ += 0x9E3779B97F4A7C15ULL;
        std::uint64_t z = state_;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    }

  private:
    std::uint64_t state_ = 5;  // radius 5: any fixed seed would do
};

// Mitchell's best-candidate sampling: each new tap is the candidate farthest from the taps
// already placed, which approximates a Poisson-disk distribution without rejection loops.
std::vector<cv::Point2f> make_taps() {
    constexpr int candidates = 32;
    SplitMix random;
    std::vector<cv::Point2f> taps{{0.0F, 0.0F}};
    while (static_cast<int>(taps.size()) < poisson_disk_tap_count) {
        cv::Point2f best;
        double best_distance = -1.0;
        for (int c = 0; c < candidates; ++c) {
            // Uniform in the unit disk: sqrt of a uniform radius.
            const double radius = std::sqrt(random.next_unit());
            const double angle = 2.0 * M_PI * random.next_unit();
            const cv::Point2f candidate(static_cast<float>(radius * std::cos(angle)),
                                        static_cast<float>(radius * std::sin(angle)));
            double nearest = 1e9;
            for (const auto& tap : taps) {
                const cv::Point2f d = candidate - tap;
                nearest = std::min(nearest, static_cast<double>(d.dot(d)));
            }
            if (nearest > best_distance) {
                best_distance = nearest;
                best = candidate;
            }
        }
        taps.push_back(best);
    }
    return taps;
}

}  // namespace

const std::vector<cv::Point2f>& poisson_disk_taps() {
    static const std::vector<cv::Point2f> taps = make_taps();
    return taps;
}

}  // namespace raypoint::core
