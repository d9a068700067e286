// SPDX-License-Identifier: MIT
#include "raypoint/loop/latency_histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace raypoint::daemon {

int LatencyHistogram::bucket_of(Microseconds value) noexcept {
    if (value < exact_limit) return static_cast<int>(std::max<Microseconds>(value, 0));
    const int octave = static_cast<int>(std::bit_width(static_cast<std::uint64_t>(value))) - 1;
    if (octave >= 7 + octaves) return bucket_count - 1;
    // The top 7 bits of the value: 64 + the sub-bucket within its power of two.
    const auto top = static_cast<int>(value >> (octave - 6));
    return exact_limit + (octave - 7) * sub_buckets + (top - sub_buckets);
}

LatencyHistogram::Microseconds LatencyHistogram::upper_bound_of(int bucket) noexcept {
    if (bucket < exact_limit) return bucket;
    const int octave = (bucket - exact_limit) / sub_buckets + 7;
    const int sub = (bucket - exact_limit) % sub_buckets;
    const Microseconds width = Microseconds{1} << (octave - 6);
    return (sub_buckets + sub) * width + width - 1;
}

void LatencyHistogram::record(Microseconds value) noexcept {
    ++buckets_[static_cast<std::size_t>(bucket_of(value))];
    ++count_;
    max_ = std::max(max_, std::max<Microseconds>(value, 0));
}

LatencyHistogram::Microseconds LatencyHistogram::quantile(double q) const noexcept {
    if (count_ == 0) return 0;
    // The rank of the quantile, 1-based: q = 0.5 of 10 values is the 5th, q = 0.99 of 10 the 10th.
    const auto rank = std::clamp<std::int64_t>(
        static_cast<std::int64_t>(std::ceil(q * static_cast<double>(count_))), 1, count_);
    std::int64_t seen = 0;
    for (int bucket = 0; bucket < bucket_count; ++bucket) {
        seen += buckets_[static_cast<std::size_t>(bucket)];
        if (seen < rank) continue;
        // The last bucket also holds everything beyond it: only the maximum bounds it.
        return bucket == bucket_count - 1 ? max_ : std::min(upper_bound_of(bucket), max_);
    }
    return max_;
}

}  // namespace raypoint::daemon
