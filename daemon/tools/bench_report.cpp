// SPDX-License-Identifier: MIT
#include "bench_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace raypoint::daemon {
namespace {

std::string format(const std::optional<double>& value, const char* pattern, double scale = 1.0) {
    if (!value || !std::isfinite(*value)) return "-";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, pattern, *value * scale);
    return buffer;
}

std::string json_number(const std::optional<double>& value, const char* pattern) {
    return value && std::isfinite(*value) ? format(value, pattern) : "null";
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out + "\"";
}

void fill_times(BenchRow& row, const std::vector<double>& microseconds) {
    row.frames = microseconds.size();
    if (microseconds.empty()) return;
    row.median_us = percentile(microseconds, 0.5);
    row.p95_us = percentile(microseconds, 0.95);
}

std::optional<double> mean(const std::vector<double>& values) {
    if (values.empty()) return std::nullopt;
    double sum = 0.0;
    for (const double v : values)
        sum += v;
    return sum / static_cast<double>(values.size());
}

// Pools one system's results over the clips.
struct Overall {
    std::vector<double> microseconds;
    int scored = 0;
    int on_target = 0;
    std::vector<double> centroid_errors, area_errors, depth_rs;
    bool has_accuracy = false;
};

void set_ratios(std::vector<BenchRow>::iterator begin, std::vector<BenchRow>::iterator end,
                const std::string& reference) {
    const auto ref =
        std::find_if(begin, end, [&](const BenchRow& r) { return r.system == reference; });
    if (ref == end || !ref->median_us || *ref->median_us <= 0.0) return;
    for (auto row = begin; row != end; ++row) {
        if (row->median_us) row->ratio = *row->median_us / *ref->median_us;
    }
}

// A row's figures after clip and system, as the table and the Markdown show them.
std::vector<std::string> cells(const BenchRow& r, const char* ratio_pattern) {
    return {std::to_string(r.frames),
            format(r.median_us, "%.0f"),
            format(r.p95_us, "%.0f"),
            format(r.ratio, ratio_pattern),
            format(r.tracked, "%.1f%%", 100.0),
            format(r.centroid_error, "%.2f"),
            format(r.area_error, "%.1f%%", 100.0),
            format(r.depth_r, "%.3f")};
}

}  // namespace

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double position = fraction * static_cast<double>(values.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, values.size() - 1);
    const double weight = position - static_cast<double>(below);
    return values[below] + weight * (values[above] - values[below]);
}

std::vector<BenchRow> bench_rows(const std::vector<ClipResults>& clips,
                                 const std::string& reference) {
    std::vector<BenchRow> rows;
    std::vector<std::string> order;
    std::map<std::string, Overall> overall;
    for (const ClipResults& clip : clips) {
        const std::size_t first = rows.size();
        for (const SystemResult& system : clip.systems) {
            BenchRow row;
            row.clip = clip.clip;
            row.system = system.system;
            row.error = system.error;
            fill_times(row, system.microseconds);
            if (std::find(order.begin(), order.end(), system.system) == order.end()) {
                order.push_back(system.system);
            }
            Overall& pool = overall[system.system];
            pool.microseconds.insert(pool.microseconds.end(), system.microseconds.begin(),
                                     system.microseconds.end());
            if (system.accuracy) {
                const scene::Evaluation& a = *system.accuracy;
                row.tracked = a.tracked();
                row.centroid_error = a.median_centroid_error;
                row.area_error = a.median_area_error;
                row.depth_r = a.depth_correlation;
                pool.has_accuracy = true;
                pool.scored += a.scored_frames;
                pool.on_target += a.on_target;
                if (a.median_centroid_error)
                    pool.centroid_errors.push_back(*a.median_centroid_error);
                if (a.median_area_error) pool.area_errors.push_back(*a.median_area_error);
                if (a.depth_correlation) pool.depth_rs.push_back(*a.depth_correlation);
            }
            rows.push_back(row);
        }
        set_ratios(rows.begin() + static_cast<std::ptrdiff_t>(first), rows.end(), reference);
    }
    if (clips.size() < 2) return rows;
    const std::size_t first = rows.size();
    for (const std::string& system : order) {
        const Overall& pool = overall[system];
        BenchRow row;
        row.clip = "overall";
        row.system = system;
        fill_times(row, pool.microseconds);
        if (pool.has_accuracy) {
            row.tracked = pool.scored == 0 ? 0.0 : double(pool.on_target) / pool.scored;
            row.centroid_error = mean(pool.centroid_errors);
            row.area_error = mean(pool.area_errors);
            row.depth_r = mean(pool.depth_rs);
        }
        rows.push_back(row);
    }
    set_ratios(rows.begin() + static_cast<std::ptrdiff_t>(first), rows.end(), reference);
    return rows;
}

void print_rows(std::FILE* out, const std::vector<BenchRow>& rows, BenchFormat format_kind) {
    constexpr std::array<int, 8> widths = {6, 9, 9, 9, 8, 8, 9, 8};
    constexpr std::array<const char*, 8> table_heads = {
        "frames", "median us", "p95 us", "x default", "tracked", "cerr px", "area err", "depth r"};
    for (const BenchRow& r : rows) {
        const bool first = &r == &rows.front();
        switch (format_kind) {
            case BenchFormat::table: {
                if (first) std::fprintf(out, "%-12s %-25s", "clip", "system");
                for (std::size_t i = 0; first && i < widths.size(); ++i)
                    std::fprintf(out, " %*s", widths[i], table_heads[i]);
                if (first) std::fputc('\n', out);
                std::fprintf(out, "%-12s %-25s", r.clip.c_str(), r.system.c_str());
                if (!r.error.empty()) std::fprintf(out, " error: %s", r.error.c_str());
                const auto values = cells(r, "%.2fx");
                for (std::size_t i = 0; r.error.empty() && i < widths.size(); ++i)
                    std::fprintf(out, " %*s", widths[i], values[i].c_str());
                std::fputc('\n', out);
                break;
            }
            case BenchFormat::markdown: {
                if (first) {
                    std::fputs(
                        "| clip | system | frames | median µs | p95 µs | × default | "
                        "tracked | centroid error px | area error | depth r |\n"
                        "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n",
                        out);
                }
                std::fprintf(out, "| %s | %s |", r.clip.c_str(), r.system.c_str());
                if (!r.error.empty()) std::fprintf(out, " error: %s ||||||||", r.error.c_str());
                for (const std::string& value :
                     r.error.empty() ? cells(r, "%.2f×") : std::vector<std::string>{})
                    std::fprintf(out, " %s |", value.c_str());
                std::fputc('\n', out);
                break;
            }
            case BenchFormat::jsonl: {
                const std::string error =
                    r.error.empty() ? std::string() : ",\"error\":" + json_string(r.error);
                std::fprintf(
                    out,
                    "{\"clip\":%s,\"system\":%s,\"frames\":%zu,\"median_us\":%s,"
                    "\"p95_us\":%s,\"ratio\":%s,\"tracked\":%s,\"cerr\":%s,\"area\":%s,"
                    "\"depth_r\":%s%s}\n",
                    json_string(r.clip).c_str(), json_string(r.system).c_str(), r.frames,
                    json_number(r.median_us, "%.1f").c_str(), json_number(r.p95_us, "%.1f").c_str(),
                    json_number(r.ratio, "%.3f").c_str(), json_number(r.tracked, "%.4f").c_str(),
                    json_number(r.centroid_error, "%.3f").c_str(),
                    json_number(r.area_error, "%.4f").c_str(),
                    json_number(r.depth_r, "%.4f").c_str(), error.c_str());
                break;
            }
        }
    }
}

}  // namespace raypoint::daemon
