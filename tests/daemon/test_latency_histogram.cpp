// SPDX-License-Identifier: MIT
// The daemon's latency histogram: exact below 128 us, within its 1/64 bucket width above, and
// quantiles that agree with sorting the same values.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/loop/latency_histogram.hpp"

namespace raypoint::daemon {
namespace {

// The q-quantile of `values` by the histogram's rank rule (the ceil(q * n)-th smallest).
std::int64_t sorted_quantile(std::vector<std::int64_t> values, double q) {
    std::sort(values.begin(), values.end());
    const auto rank =
        static_cast<std::size_t>(std::max(1.0, std::ceil(q * static_cast<double>(values.size()))));
    return values[rank - 1];
}

TEST(LatencyHistogram, EmptySaysZero) {
    const LatencyHistogram histogram;
    EXPECT_EQ(histogram.count(), 0);
    EXPECT_EQ(histogram.quantile(0.5), 0);
    EXPECT_EQ(histogram.max(), 0);
}

TEST(LatencyHistogram, ExactBelow128Microseconds) {
    LatencyHistogram histogram;
    for (int value = 1; value <= 100; ++value)
        histogram.record(value);
    EXPECT_EQ(histogram.count(), 100);
    EXPECT_EQ(histogram.quantile(0.5), 50);
    EXPECT_EQ(histogram.quantile(0.99), 99);
    EXPECT_EQ(histogram.quantile(1.0), 100);
    EXPECT_EQ(histogram.quantile(0.0), 1);
    EXPECT_EQ(histogram.max(), 100);
}

TEST(LatencyHistogram, QuantilesWithinOneBucketOfSorting) {
    // Log-uniform from 10 us to 100 ms: every octave of the histogram in use.
    std::mt19937 random(5);
    std::uniform_real_distribution<double> exponent(1.0, 5.0);
    std::vector<std::int64_t> values;
    LatencyHistogram histogram;
    for (int i = 0; i < 20'000; ++i) {
        const auto value = static_cast<std::int64_t>(std::pow(10.0, exponent(random)));
        values.push_back(value);
        histogram.record(value);
    }
    for (const double q : {0.01, 0.1, 0.5, 0.9, 0.99, 0.999}) {
        const std::int64_t exact = sorted_quantile(values, q);
        const std::int64_t binned = histogram.quantile(q);
        // The upper bound of the value's bucket: never below, at most 1/64 of it above.
        EXPECT_GE(binned, exact) << "q " << q;
        EXPECT_LE(static_cast<double>(binned), static_cast<double>(exact) * (1.0 + 1.0 / 64.0))
            << "q " << q;
    }
    EXPECT_EQ(histogram.max(), *std::max_element(values.begin(), values.end()));
}

TEST(LatencyHistogram, BucketEdgesAroundPowersOfTwo) {
    for (const std::int64_t value : {127, 128, 129, 255, 256, 257, 1023, 1024, 65'535, 65'536}) {
        LatencyHistogram histogram;
        histogram.record(value);
        histogram.record(10 * value);  // the median is then `value`'s bucket's upper bound
        const std::int64_t median = histogram.quantile(0.5);
        EXPECT_GE(median, value) << value;
        EXPECT_LE(static_cast<double>(median), static_cast<double>(value) * (1.0 + 1.0 / 64.0))
            << value;
        if (value < 128) {
            EXPECT_EQ(median, value);
        }
    }
}

TEST(LatencyHistogram, NegativeCountsAsZeroAndHugeIsKeptAsMax) {
    LatencyHistogram histogram;
    histogram.record(-40);  // the frame's clock ahead of ours: not a negative latency
    EXPECT_EQ(histogram.quantile(1.0), 0);
    const std::int64_t ten_minutes = 600'000'000;  // past the last octave
    histogram.record(ten_minutes);
    EXPECT_EQ(histogram.count(), 2);
    EXPECT_EQ(histogram.max(), ten_minutes);
    EXPECT_EQ(histogram.quantile(1.0), ten_minutes);
    histogram.clear();
    EXPECT_EQ(histogram.count(), 0);
}

}  // namespace
}  // namespace raypoint::daemon
