// SPDX-License-Identifier: MIT
// Every key of the schema through the INI path: range edges accepted and set exactly, one step
// outside rejected with the exact "file:line: [section] key: reason (allowed: range)" message,
// every choice accepted, wrong types rejected.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "ini_testing.hpp"

namespace raypoint::config {
namespace {

using testing::formatted;
using testing::load_text;

std::string number_text(const Key& key, double value) {
    if (key.type == ValueType::integer) return std::to_string(static_cast<long long>(value));
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

// The key on line 3, after a comment, so a wrong line number shows.
std::string file_with(const Key& key, std::string_view value) {
    return "# edge\n[" + std::string(key.section) + "]\n" + std::string(key.name) + " = " +
           std::string(value) + "\n";
}

std::string message(const Key& key, std::string_view reason) {
    return "t.ini:3: [" + std::string(key.section) + "] " + std::string(key.name) + ": " +
           std::string(reason) + " (allowed: " + key.allowed() + ")";
}

std::string type_reason(const Key& key) {
    switch (key.type) {
        case ValueType::integer:
            return "not an integer";
        case ValueType::real:
            return "not a number";
        case ValueType::boolean:
            return "not a boolean";
        case ValueType::choice:
            return "unknown value";
        case ValueType::device:
            return "not a device";
    }
    return {};
}

TEST(IniRanges, NumericEdgesAcceptedAndOneStepOutsideRejected) {
    int checked = 0;
    for (const Key& key : schema()) {
        if (key.type != ValueType::integer && key.type != ValueType::real) continue;
        SCOPED_TRACE(key.full_name());
        for (const double edge : {key.min, key.max}) {
            const auto loaded = load_text(file_with(key, number_text(key, edge)));
            EXPECT_EQ(loaded.errors, std::vector<std::string>{});
            ASSERT_EQ(loaded.file.settings.size(), 1U);
            EXPECT_EQ(loaded.file.settings[0].line, 3);
            EXPECT_EQ(std::stod(key.format(loaded.config)), edge);
        }
        const double step =
            key.type == ValueType::integer
                ? 1.0
                : std::max(1e-6, std::max(std::abs(key.min), std::abs(key.max)) * 1e-9);
        for (const double outside : {key.min - step, key.max + step}) {
            const auto loaded = load_text(file_with(key, number_text(key, outside)));
            EXPECT_EQ(loaded.errors, std::vector<std::string>{message(key, "value out of range")});
            EXPECT_TRUE(loaded.file.settings.empty());
            EXPECT_EQ(formatted(loaded.config), formatted(Config{}));
        }
        ++checked;
    }
    EXPECT_GE(checked, 20);
}

TEST(IniRanges, EveryChoiceAcceptedAndAnOtherWordRejected) {
    int checked = 0;
    for (const Key& key : schema()) {
        if (key.type != ValueType::choice && key.type != ValueType::boolean) continue;
        SCOPED_TRACE(key.full_name());
        for (const auto choice : key.choices) {
            const auto loaded = load_text(file_with(key, choice));
            EXPECT_EQ(loaded.errors, std::vector<std::string>{});
            EXPECT_EQ(key.format(loaded.config), choice);
        }
        const auto loaded = load_text(file_with(key, "nope"));
        EXPECT_EQ(loaded.errors, std::vector<std::string>{message(key, type_reason(key))});
        ++checked;
    }
    EXPECT_GE(checked, 5);
}

TEST(IniRanges, WrongTypesAndEmptyValues) {
    for (const Key& key : schema()) {
        SCOPED_TRACE(key.full_name());
        for (const char* wrong : {"", "12abc", "x"}) {
            const auto loaded = load_text(file_with(key, wrong));
            EXPECT_EQ(loaded.errors, std::vector<std::string>{message(key, type_reason(key))})
                << '"' << wrong << '"';
        }
    }
    const Key& rays = *find_key("estimator", "rays");
    EXPECT_EQ(load_text(file_with(rays, "8.5")).errors,
              std::vector<std::string>{message(rays, "not an integer")});
    EXPECT_EQ(load_text(file_with(rays, "\"8\"")).errors,
              std::vector<std::string>{message(rays, "not an integer")});
}

TEST(IniRanges, BooleanSpellingsAsInSet) {
    const Key& key = *find_key("tracking", "keep_still_target");
    for (const char* yes : {"true", "yes", "on", "1"}) {
        const auto loaded = load_text(file_with(key, yes), "paper");  // paper: false
        EXPECT_EQ(loaded.errors, std::vector<std::string>{});
        EXPECT_TRUE(loaded.config.core.tracking.keep_still_target) << yes;
    }
    for (const char* no : {"false", "no", "off", "0"}) {
        const auto loaded = load_text(file_with(key, no));
        EXPECT_EQ(loaded.errors, std::vector<std::string>{});
        EXPECT_FALSE(loaded.config.core.tracking.keep_still_target) << no;
    }
}

}  // namespace
}  // namespace raypoint::config
