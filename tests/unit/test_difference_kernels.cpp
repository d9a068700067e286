// SPDX-License-Identifier: MIT
// The difference stage's kernels (core/src/difference_kernels.hpp), portable and SSE2, against
// definitions computed here: the paper's offset from a 256-bin histogram (the largest of the
// `minima` smallest distinct values), sums of max(0, value - offset), per-pixel channel maxima.
// Lengths around the vector widths and value spreads from dense noise to a few far values.

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "difference_kernels.hpp"

namespace raypoint::core::detail {
namespace {

int reference_offset(const std::vector<std::uint8_t>& values, int minima) {
    std::array<int, 256> histogram{};
    for (const std::uint8_t value : values)
        ++histogram[value];
    int distinct = 0;
    int largest = 0;
    for (int value = 0; value < 256 && distinct < minima; ++value) {
        if (histogram[value] == 0) continue;
        ++distinct;
        largest = value;
    }
    return largest;
}

std::int64_t reference_sum(const std::vector<std::uint8_t>& values, int offset) {
    std::int64_t sum = 0;
    for (const std::uint8_t value : values)
        sum += std::max(0, value - offset);
    return sum;
}

// Values of a kind: dense noise from `low`, a few far values, or both.
std::vector<std::uint8_t> values_of(std::size_t length, int kind, std::mt19937& random) {
    std::vector<std::uint8_t> values(length);
    std::uniform_int_distribution<int> noise(0, 12);
    std::uniform_int_distribution<int> any(0, 255);
    std::uniform_int_distribution<int> percent(0, 99);
    for (std::uint8_t& value : values) {
        switch (kind) {
            case 0:
                value = static_cast<std::uint8_t>(noise(random));
                break;
            case 1:
                value = static_cast<std::uint8_t>(40 + 20 * (any(random) % 4));
                break;
            case 2:
                value = static_cast<std::uint8_t>(any(random));
                break;
            case 3:  // mostly one value, a few spread over the range, 255 among them
                value = static_cast<std::uint8_t>(percent(random) < 97 ? 7 : 248 + any(random) % 8);
                break;
            default:  // noise and a moving edge's far values
                value = static_cast<std::uint8_t>(percent(random) < 90 ? 3 + noise(random) / 4
                                                                       : any(random));
        }
    }
    return values;
}

const std::vector<std::size_t> lengths = {0,   1,   15,  16,  17,    31,   64,
                                          127, 128, 129, 200, 19200, 19207};

template <typename Kernels>
void check_offsets_and_sums() {
    std::mt19937 random(7);
    for (const std::size_t length : lengths) {
        for (int kind = 0; kind < 5; ++kind) {
            std::vector<std::uint8_t> values = values_of(length, kind, random);
            const std::uint8_t smallest =
                length == 0 ? 255 : *std::min_element(values.begin(), values.end());
            for (const int minima : {0, 1, 2, 3, 10, 300}) {
                const int expected = reference_offset(values, minima);
                EXPECT_EQ(Kernels::distinct_offset(values.data(), length, smallest, minima),
                          expected)
                    << "length " << length << " kind " << kind << " minima " << minima;
            }
            for (const int offset : {0, 1, 9, 200, 255}) {
                const auto subtrahend = static_cast<std::uint8_t>(offset);
                EXPECT_EQ(Kernels::compensated_sum(values.data(), length, subtrahend),
                          reference_sum(values, offset));
                std::vector<std::uint8_t> compensated = values;
                EXPECT_EQ(Kernels::compensate(compensated.data(), length, subtrahend),
                          reference_sum(values, offset));
                for (std::size_t i = 0; i < length; ++i)
                    ASSERT_EQ(compensated[i], std::max(0, values[i] - offset));
            }
        }
    }
}

template <typename Kernels>
void check_differences() {
    std::mt19937 random(11);
    for (const std::size_t length : lengths) {
        for (int kind = 0; kind < 5; ++kind) {
            const std::vector<std::uint8_t> a = values_of(3 * length, kind, random);
            const std::vector<std::uint8_t> b = values_of(3 * length, (kind + 2) % 5, random);
            const int count = static_cast<int>(length);
            // Grey: each byte's difference, and the smallest of them and the starting value.
            std::vector<std::uint8_t> out(length);
            const std::uint8_t least =
                Kernels::absolute_difference(a.data(), b.data(), out.data(), count, 200);
            std::uint8_t expected_least = 200;
            for (std::size_t i = 0; i < length; ++i) {
                const auto difference = static_cast<std::uint8_t>(std::abs(a[i] - b[i]));
                ASSERT_EQ(out[i], difference);
                expected_least = std::min(expected_least, difference);
            }
            EXPECT_EQ(least, expected_least);
            // Channels: the same maxima in some order.
            std::vector<std::uint8_t> strongest(length);
            std::vector<std::uint8_t> expected(length);
            expected_least = 255;
            for (std::size_t x = 0; x < length; ++x) {
                for (std::size_t c = 0; c < 3; ++c) {
                    const auto difference =
                        static_cast<std::uint8_t>(std::abs(a[3 * x + c] - b[3 * x + c]));
                    expected[x] = std::max(expected[x], difference);
                }
                expected_least = std::min(expected_least, expected[x]);
            }
            EXPECT_EQ(Kernels::strongest_channel(a.data(), b.data(), strongest.data(), count, 255),
                      expected_least);
            std::sort(strongest.begin(), strongest.end());
            std::sort(expected.begin(), expected.end());
            EXPECT_EQ(strongest, expected) << "pixels " << length << " kind " << kind;
        }
    }
}

struct Portable {
    static constexpr auto absolute_difference = portable::absolute_difference;
    static constexpr auto strongest_channel = portable::strongest_channel;
    static constexpr auto distinct_offset = portable::distinct_offset;
    static constexpr auto compensate = portable::compensate;
    static constexpr auto compensated_sum = portable::compensated_sum;
};

TEST(DifferenceKernels, PortableOffsetsAndSumsAreTheHistogramsOnes) {
    check_offsets_and_sums<Portable>();
}

TEST(DifferenceKernels, PortableDifferencesAndChannelMaxima) {
    check_differences<Portable>();
}

#if defined(__x86_64__) && defined(__GNUC__)
struct Sse2 {
    static constexpr auto absolute_difference = sse2::absolute_difference;
    static constexpr auto strongest_channel = sse2::strongest_channel;
    static constexpr auto distinct_offset = sse2::distinct_offset;
    static constexpr auto compensate = sse2::compensate;
    static constexpr auto compensated_sum = sse2::compensated_sum;
};

TEST(DifferenceKernels, Sse2OffsetsAndSumsAreTheHistogramsOnes) {
    check_offsets_and_sums<Sse2>();
}

TEST(DifferenceKernels, Sse2DifferencesAndChannelMaxima) {
    check_differences<Sse2>();
}
#endif

}  // namespace
}  // namespace raypoint::core::detail
