// SPDX-License-Identifier: MIT
#pragma once
// The figures `raypoint bench` prints: per clip and overall, each system's median and p95
// microseconds a frame, its ratio to raypoint's default estimator, and its accuracy.

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "bench_runner.hpp"

namespace raypoint::daemon {

enum class BenchFormat { table, markdown, jsonl };

struct ClipResults {
    std::string clip;
    std::string size;  // "640x480"
    std::vector<SystemResult> systems;
};

struct BenchRow {
    std::string clip;
    std::string system;
    std::size_t frames = 0;  // timed frames
    std::optional<double> median_us;
    std::optional<double> p95_us;
    std::optional<double> ratio;  // median / the reference system's median
    std::optional<double> tracked;
    std::optional<double> centroid_error;  // px at 160x120
    std::optional<double> area_error;      // relative
    std::optional<double> depth_r;
    std::string error;
};

// The rows: every clip's systems, then "overall" ones: times pooled over every clip's timed
// frames, tracked pooled over every scored frame, and the other accuracy columns the mean of
// the clips' values. `reference` names the system the ratios divide by.
std::vector<BenchRow> bench_rows(const std::vector<ClipResults>& clips,
                                 const std::string& reference);

void print_rows(std::FILE* out, const std::vector<BenchRow>& rows, BenchFormat format);

// numpy's median and linear-interpolation percentile, so the figures compare with the scoring
// method's (docs/scoring.md).
double percentile(std::vector<double> values, double fraction);

}  // namespace raypoint::daemon
