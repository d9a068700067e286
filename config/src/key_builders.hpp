// SPDX-License-Identifier: MIT
#pragma once
// Builders for schema rows: each binds a key to one field of Config through an accessor.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <span>
#include <utility>

#include "raypoint/config/schema.hpp"

namespace raypoint::config::detail {

std::string format_real(double value);
std::optional<double> parse_number(std::string_view text);

// A row without its format, parse and assign, which each builder adds.
inline Key row(std::string_view section, std::string_view name, ValueType type,
               std::string_view doc, double min = 0.0, double max = 0.0) {
    Key key;
    key.section = section;
    key.name = name;
    key.type = type;
    key.min = min;
    key.max = max;
    key.doc = doc;
    return key;
}

template <typename Access>
Key integer_key(std::string_view section, std::string_view name, int min, int max,
                std::string_view doc, Access access) {
    Key key = row(section, name, ValueType::integer, doc, min, max);
    key.format = [access](const Config& c) { return std::to_string(access(c)); };
    key.parse = [min, max](std::string_view text, Value& parsed) -> std::optional<std::string> {
        int value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) return "not an integer";
        if (value < min || value > max) return "value out of range";
        parsed = value;
        return std::nullopt;
    };
    key.assign = [access](Config& c, const Value& value) { access(c) = std::get<int>(value); };
    return key;
}

template <typename Access>
Key real_key(std::string_view section, std::string_view name, double min, double max,
             std::string_view doc, Access access) {
    Key key = row(section, name, ValueType::real, doc, min, max);
    key.format = [access](const Config& c) { return format_real(access(c)); };
    key.parse = [min, max](std::string_view text, Value& parsed) -> std::optional<std::string> {
        const auto value = parse_number(text);
        if (!value) return "not a number";
        if (*value < min || *value > max) return "value out of range";
        parsed = *value;
        return std::nullopt;
    };
    key.assign = [access](Config& c, const Value& value) { access(c) = std::get<double>(value); };
    return key;
}

template <typename Access>
Key boolean_key(std::string_view section, std::string_view name, std::string_view doc,
                Access access) {
    Key key = row(section, name, ValueType::boolean, doc, 0, 1);
    key.choices = {"true", "false"};
    key.format = [access](const Config& c) { return std::string(access(c) ? "true" : "false"); };
    key.parse = [](std::string_view text, Value& parsed) -> std::optional<std::string> {
        if (text == "true" || text == "yes" || text == "on" || text == "1") {
            parsed = true;
        } else if (text == "false" || text == "no" || text == "off" || text == "0") {
            parsed = false;
        } else {
            return "not a boolean";
        }
        return std::nullopt;
    };
    key.assign = [access](Config& c, const Value& value) { access(c) = std::get<bool>(value); };
    return key;
}

// A device path: `auto` or an absolute path under /dev (/dev/video0, /dev/v4l/by-id/...).
template <typename Access>
Key device_key(std::string_view section, std::string_view name, std::string_view doc,
               Access access) {
    Key key = row(section, name, ValueType::device, doc);
    key.format = [access](const Config& c) { return access(c); };
    key.parse = [](std::string_view text, Value& parsed) -> std::optional<std::string> {
        const bool path = text.size() > 5 && text.substr(0, 5) == "/dev/" &&
                          text.find_first_of(" \t") == std::string_view::npos;
        if (text != "auto" && !path) return "not a device";
        parsed = std::string(text);
        return std::nullopt;
    };
    key.assign = [access](Config& c, const Value& value) {
        access(c) = std::get<std::string>(value);
    };
    return key;
}

// `names` lists each enumerator's text, in any order.
template <typename Enum, typename Access>
Key choice_key(std::string_view section, std::string_view name, std::string_view doc,
               std::vector<std::pair<Enum, std::string_view>> names, Access access) {
    Key key = row(section, name, ValueType::choice, doc);
    for (const auto& entry : names)
        key.choices.push_back(entry.second);
    key.format = [access, names](const Config& c) {
        for (const auto& [value, text] : names) {
            if (value == access(c)) return std::string(text);
        }
        return std::string("?");
    };
    // Exact, else the one choice equal but for case ("Absolute" is absolute: the values are
    // lower case, and no two differ only in case); else the reason, with the closest choice.
    key.parse = [names](std::string_view text, Value& parsed) -> std::optional<std::string> {
        const auto lower = [](std::string_view s) {
            std::string out(s);
            for (char& c : out)
                if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
            return out;
        };
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names[i].second == text) {
                parsed = ChoiceIndex{i};
                return std::nullopt;
            }
        }
        std::string best;
        std::size_t best_distance = SIZE_MAX;
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (lower(names[i].second) == lower(text)) {
                parsed = ChoiceIndex{i};
                return std::nullopt;
            }
            const std::size_t distance = edit_distance(lower(text), names[i].second);
            if (distance < best_distance) {
                best_distance = distance;
                best = names[i].second;
            }
        }
        if (!similar(best_distance, text.size())) return "unknown value";
        return "unknown value, did you mean " + best + "?";
    };
    key.assign = [access, names](Config& c, const Value& value) {
        access(c) = names[std::get<ChoiceIndex>(value).index].first;
    };
    return key;
}

// The keys of [output], [pointer], [click], [dwell], [safety] and [camera], in that order
// (schema_output_table.cpp); schema() puts them after the tracker's.
std::vector<Key> output_keys();

}  // namespace raypoint::config::detail
