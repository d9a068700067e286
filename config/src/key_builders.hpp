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

template <typename Access>
Key integer_key(std::string_view section, std::string_view name, int min, int max,
                std::string_view doc, Access access) {
    Key key{section,
            name,
            ValueType::integer,
            static_cast<double>(min),
            static_cast<double>(max),
            {},
            doc,
            nullptr,
            nullptr};
    key.format = [access](const Config& c) { return std::to_string(access(c)); };
    key.parse = [access, min, max](Config& c, std::string_view text) -> std::optional<std::string> {
        int value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) return "not an integer";
        if (value < min || value > max) return "value out of range";
        access(c) = value;
        return std::nullopt;
    };
    return key;
}

template <typename Access>
Key real_key(std::string_view section, std::string_view name, double min, double max,
             std::string_view doc, Access access) {
    Key key{section, name, ValueType::real, min, max, {}, doc, nullptr, nullptr};
    key.format = [access](const Config& c) { return format_real(access(c)); };
    key.parse = [access, min, max](Config& c, std::string_view text) -> std::optional<std::string> {
        const auto value = parse_number(text);
        if (!value) return "not a number";
        if (*value < min || *value > max) return "value out of range";
        access(c) = *value;
        return std::nullopt;
    };
    return key;
}

template <typename Access>
Key boolean_key(std::string_view section, std::string_view name, std::string_view doc,
                Access access) {
    Key key{section, name, ValueType::boolean, 0, 1, {"true", "false"}, doc, nullptr, nullptr};
    key.format = [access](const Config& c) { return std::string(access(c) ? "true" : "false"); };
    key.parse = [access](Config& c, std::string_view text) -> std::optional<std::string> {
        if (text == "true" || text == "yes" || text == "on" || text == "1") {
            access(c) = true;
        } else if (text == "false" || text == "no" || text == "off" || text == "0") {
            access(c) = false;
        } else {
            return "not a boolean";
        }
        return std::nullopt;
    };
    return key;
}

// A device path: `auto` or an absolute path under /dev (/dev/video0, /dev/v4l/by-id/...).
template <typename Access>
Key device_key(std::string_view section, std::string_view name, std::string_view doc,
               Access access) {
    Key key{section, name, ValueType::device, 0, 0, {}, doc, nullptr, nullptr};
    key.format = [access](const Config& c) { return access(c); };
    key.parse = [access](Config& c, std::string_view text) -> std::optional<std::string> {
        const bool path = text.size() > 5 && text.substr(0, 5) == "/dev/" &&
                          text.find_first_of(" \t") == std::string_view::npos;
        if (text != "auto" && !path) return "not a device";
        access(c) = std::string(text);
        return std::nullopt;
    };
    return key;
}

// `names` lists each enumerator's text, in any order.
template <typename Enum, typename Access>
Key choice_key(std::string_view section, std::string_view name, std::string_view doc,
               std::vector<std::pair<Enum, std::string_view>> names, Access access) {
    Key key{section, name, ValueType::choice, 0, 0, {}, doc, nullptr, nullptr};
    for (const auto& entry : names)
        key.choices.push_back(entry.second);
    key.format = [access, names](const Config& c) {
        for (const auto& [value, text] : names) {
            if (value == access(c)) return std::string(text);
        }
        return std::string("?");
    };
    key.parse = [access, names](Config& c, std::string_view text) -> std::optional<std::string> {
        for (const auto& [value, known] : names) {
            if (known == text) {
                access(c) = value;
                return std::nullopt;
            }
        }
        return "unknown value";
    };
    return key;
}

}  // namespace raypoint::config::detail
