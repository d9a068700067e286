// SPDX-License-Identifier: MIT
#include <algorithm>
#include <sstream>

#include "key_builders.hpp"

namespace raypoint::config {

namespace detail {

// Shortest text that reads back as the same double: "0.9", not "0.900000". Whole numbers are
// written out ("9600", not "9.6e+03"): they are what people type in an INI file.
std::string format_real(double value) {
    char buffer[64];
    if (value == std::floor(value) && std::abs(value) < 1e15) {
        std::snprintf(buffer, sizeof buffer, "%.0f", value);
        return buffer;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

std::optional<double> parse_number(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

}  // namespace detail

std::string Key::full_name() const {
    return std::string(section) + "." + std::string(name);
}

std::string Key::allowed() const {
    switch (type) {
        case ValueType::integer:
            return std::to_string(static_cast<long long>(min)) + ".." +
                   std::to_string(static_cast<long long>(max));
        case ValueType::real:
            return detail::format_real(min) + ".." + detail::format_real(max);
        case ValueType::device:
            return "auto|/dev/...";
        case ValueType::boolean:
        case ValueType::choice: {
            std::string text;
            for (const auto& choice : choices) {
                if (!text.empty()) text += "|";
                text += choice;
            }
            return text;
        }
    }
    return {};
}

std::optional<std::string> Key::set(Config& config, std::string_view text) const {
    Value value;
    if (auto reason = parse(text, value)) return reason;
    assign(config, value);
    return std::nullopt;
}

const Key* find_key(std::string_view section, std::string_view name) noexcept {
    for (const auto& key : schema()) {
        if (key.section == section && key.name == name) return &key;
    }
    return nullptr;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string nearest_key(std::string_view wanted) {
    std::string best;
    std::size_t best_distance = SIZE_MAX;
    for (const auto& key : schema()) {
        const std::string name = key.full_name();
        // A bare key name ("min_area") is as good as a full one.
        const std::size_t distance =
            std::min(edit_distance(wanted, name), edit_distance(wanted, key.name));
        if (distance < best_distance) {
            best_distance = distance;
            best = name;
        }
    }
    return similar(best_distance, wanted.size()) ? best : std::string();
}

std::string did_you_mean(const std::string& suggestion, std::string_view otherwise) {
    if (suggestion.empty()) return " (" + std::string(otherwise) + ")";
    return " (did you mean " + suggestion + "?)";
}

std::string nearest_section(std::string_view wanted, std::span<const std::string_view> extra) {
    std::string_view best;
    std::size_t best_distance = SIZE_MAX;
    const auto consider = [&](std::string_view section) {
        const std::size_t distance = edit_distance(wanted, section);
        if (distance < best_distance) {
            best_distance = distance;
            best = section;
        }
    };
    for (const auto& key : schema())
        consider(key.section);
    for (const auto section : extra)
        consider(section);
    return similar(best_distance, wanted.size()) ? std::string(best) : std::string();
}

void apply_assignment(Config& config, std::string_view assignment) {
    const std::string shown(assignment);
    const auto equals = assignment.find('=');
    const auto dot = assignment.substr(0, equals).find('.');
    if (equals == std::string_view::npos || dot == std::string_view::npos) {
        throw ConfigError("--set " + shown + ": expected section.key=value");
    }
    const auto section = assignment.substr(0, dot);
    const auto name = assignment.substr(dot + 1, equals - dot - 1);
    const auto value = assignment.substr(equals + 1);
    const Key* key = find_key(section, name);
    if (key == nullptr) {
        throw ConfigError("--set " + shown + ": unknown key" +
                          did_you_mean(nearest_key(assignment.substr(0, equals)),
                                       "raypoint print-config lists every key"));
    }
    if (const auto reason = key->set(config, value)) {
        throw ConfigError("--set " + shown + ": " + *reason + " (allowed: " + key->allowed() + ")");
    }
}

std::vector<std::string> cross_check(const Config& config) {
    std::vector<std::string> problems;
    const auto& tracking = config.core.tracking;
    if (tracking.min_area >= tracking.max_area) {
        problems.push_back("tracking.min_area must be below tracking.max_area");
    }
    if (tracking.idle_threshold > tracking.search_threshold) {
        problems.push_back("tracking.idle_threshold must not exceed tracking.search_threshold");
    }
    if (tracking.color_patch % 2 == 0) {
        problems.push_back("tracking.color_patch must be odd, so the square has a centre");
    }
    const auto& preprocess = config.core.preprocess;
    if (config.core.estimator.block_size >
        std::min(preprocess.work_width, preprocess.work_height)) {
        problems.push_back("estimator.block_size must fit in the working image");
    }
    // Broken pointer settings never make the pointer divide by zero (an empty active region maps
    // the whole frame), but clicks would do what the values say.
    const auto& motion = config.core.pointer.motion;
    if (!(motion.active_left < motion.active_right)) {
        problems.push_back("pointer.active_left must be below pointer.active_right");
    }
    if (!(motion.active_top < motion.active_bottom)) {
        problems.push_back("pointer.active_top must be below pointer.active_bottom");
    }
    const auto& click = config.core.pointer.click;
    if (!(click.release_rise < click.press_rise)) {
        problems.push_back(
            "click.release_rise must be below click.press_rise, or a press releases at once");
    }
    if (!(click.start_rise < click.press_rise)) {
        problems.push_back(
            "click.start_rise must be below click.press_rise: a push begins before it presses");
    }
    return problems;
}

std::string to_ini(const Config& config) {
    const Config defaults;
    std::ostringstream out;
    out << "# raypoint configuration. Every key, its default and its allowed values;\n"
           "# see raypoint.ini(5) for where raypoint looks for this file.\n";
    std::string_view section;
    for (const auto& key : schema()) {
        if (key.section != section) {
            section = key.section;
            out << "\n[" << section << "]\n";
        }
        out << "# " << key.doc << "\n# allowed: " << key.allowed()
            << ", default: " << key.format(defaults) << "\n"
            << key.name << " = " << key.format(config) << "\n";
    }
    return out.str();
}

}  // namespace raypoint::config
