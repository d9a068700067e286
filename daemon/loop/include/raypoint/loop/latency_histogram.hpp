// SPDX-License-Identifier: MIT
#pragma once
// Latencies of the frame loop (frame ready -> event written) in microseconds, kept as a fixed
// histogram so that recording one costs an index computation and an increment: no allocation
// and no sorting per frame, however long the daemon runs.
//
// Buckets: 1 us wide below 128 us (exact there), then every power of two from 128 us up is cut
// into 64 equal buckets, so a bucket is at most 1/64 (1.6%) of its value wide. The last bucket
// collects everything from about 134 s up; negative values (clocks that disagree) count as 0.

#include <array>
#include <cstdint>

namespace raypoint::daemon {

class LatencyHistogram {
  public:
    using Microseconds = std::int64_t;

    void record(Microseconds value) noexcept;
    void clear() noexcept { *this = LatencyHistogram{}; }

    std::int64_t count() const noexcept { return count_; }
    Microseconds max() const noexcept { return max_; }  // exact, 0 when empty
    // The smallest bucket upper bound with at least q of the values at or below it (q in [0,1]):
    // exact below 128 us, at most 1.6% above the true quantile beyond. 0 when empty.
    Microseconds quantile(double q) const noexcept;

  private:
    static constexpr int exact_limit = 128;  // values below are their own bucket
    static constexpr int sub_buckets = 64;   // buckets a power of two above exact_limit
    static constexpr int octaves = 20;       // 2^7 .. 2^27 us (134 s)
    static constexpr int bucket_count = exact_limit + octaves * sub_buckets;

    static int bucket_of(Microseconds value) noexcept;
    static Microseconds upper_bound_of(int bucket) noexcept;  // the largest value it holds

    std::array<std::uint32_t, bucket_count> buckets_{};
    std::int64_t count_ = 0;
    Microseconds max_ = 0;
};

}  // namespace raypoint::daemon
