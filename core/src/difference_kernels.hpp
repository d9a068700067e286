// SPDX-License-Identifier: MIT
#pragma once
// The difference stage's per-pixel work (difference_stage.cpp) without histograms: the paper's
// brightness offset (the largest of the `minima` smallest distinct values, paper 4.1) found by
// minimum passes and the compensated sum by saturating subtraction, both exact integers, so the
// portable and the SSE2 kernels give the same offsets, sums and images.

#include <cstddef>
#include <cstdint>

namespace raypoint::core::detail {

// Signatures shared by both namespaces:
//
// absolute_difference: out[i] = |a[i] - b[i]| for i < length; returns the smallest of
//   `smallest` and every out[i].
// strongest_channel: for `pixels` interleaved 3-byte pixels, the largest of the three channels'
//   |color - previous| of each pixel, written to out[0, pixels) in an order of the kernel's own
//   (a permutation within each group of 16 pixels; the offset and the sums below do not depend
//   on the order); returns the smallest of `smallest` and every value written.
// distinct_offset: the largest of the `minima` smallest distinct values of values[0, length)
//   (the largest value when fewer are distinct; 0 when length or minima is 0). `smallest` is
//   the smallest value, as the two kernels above return it.
// compensate: values[i] = max(0, values[i] - offset) in place; returns the sum of the results.
// compensated_sum: the same sum, values left as they are.
namespace portable {
std::uint8_t absolute_difference(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                                 int length, std::uint8_t smallest) noexcept;
std::uint8_t strongest_channel(const std::uint8_t* color, const std::uint8_t* previous,
                               std::uint8_t* out, int pixels, std::uint8_t smallest) noexcept;
int distinct_offset(const std::uint8_t* values, std::size_t length, std::uint8_t smallest,
                    int minima) noexcept;
std::int64_t compensate(std::uint8_t* values, std::size_t length, std::uint8_t offset) noexcept;
std::int64_t compensated_sum(const std::uint8_t* values, std::size_t length,
                             std::uint8_t offset) noexcept;
}  // namespace portable

#if defined(__x86_64__) && defined(__GNUC__)
// SSE2: every x86-64 CPU has it.
namespace sse2 {
std::uint8_t absolute_difference(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* out,
                                 int length, std::uint8_t smallest) noexcept;
std::uint8_t strongest_channel(const std::uint8_t* color, const std::uint8_t* previous,
                               std::uint8_t* out, int pixels, std::uint8_t smallest) noexcept;
int distinct_offset(const std::uint8_t* values, std::size_t length, std::uint8_t smallest,
                    int minima) noexcept;
std::int64_t compensate(std::uint8_t* values, std::size_t length, std::uint8_t offset) noexcept;
std::int64_t compensated_sum(const std::uint8_t* values, std::size_t length,
                             std::uint8_t offset) noexcept;
}  // namespace sse2
namespace difference_kernels = sse2;
#else
namespace difference_kernels = portable;
#endif

}  // namespace raypoint::core::detail
