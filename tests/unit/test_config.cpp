// SPDX-License-Identifier: MIT
// The settings schema: every key's default, range, parsing and messages; INI round trip; presets.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "raypoint/config/config.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::config {
namespace {

std::string full_text(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

// Every key's formatted value: equal configs format equally, and format is exact (shortest
// round-trip for reals), so this is a field-by-field comparison through the schema.
std::vector<std::string> formatted(const Config& config) {
    std::vector<std::string> values;
    for (const Key& key : schema())
        values.push_back(key.full_name() + "=" + key.format(config));
    return values;
}

// A valid value for `key` that differs from its default.
std::string other_value(const Key& key) {
    const std::string current = key.format(Config{});
    switch (key.type) {
        case ValueType::integer: {
            for (const double v : {std::floor((key.min + key.max) / 3.0), key.max, key.min}) {
                const std::string text = std::to_string(static_cast<long long>(v));
                if (text != current) return text;
            }
            break;
        }
        case ValueType::real: {
            // A third of the way: needs all 17 digits ("0.33333333333333331").
            for (const double v : {key.min + (key.max - key.min) / 3.0, key.max, key.min}) {
                const std::string text = full_text(v);
                if (std::stod(text) != std::stod(current)) return text;
            }
            break;
        }
        case ValueType::boolean:
            return current == "true" ? "false" : "true";
        case ValueType::device:
            return current == "auto" ? "/dev/video0" : "auto";
        case ValueType::choice:
            for (const auto choice : key.choices) {
                if (choice != current) return std::string(choice);
            }
            break;
    }
    ADD_FAILURE() << key.full_name() << ": no value other than the default";
    return current;
}

TEST(Schema, KeysAreUniqueAndFindable) {
    std::set<std::string> names;
    for (const Key& key : schema()) {
        EXPECT_TRUE(names.insert(key.full_name()).second) << key.full_name();
        EXPECT_EQ(find_key(key.section, key.name), &key);
        EXPECT_FALSE(key.doc.empty()) << key.full_name();
    }
    EXPECT_GE(names.size(), 30U);
    EXPECT_EQ(find_key("tracking", "nope"), nullptr);
}

TEST(Schema, EveryDefaultFormatsAndParsesBack) {
    for (const Key& key : schema()) {
        SCOPED_TRACE(key.full_name());
        const std::string text = key.format(Config{});
        Config changed;
        ASSERT_EQ(key.set(changed, other_value(key)), std::nullopt);
        ASSERT_NE(key.format(changed), text);
        EXPECT_EQ(key.set(changed, text), std::nullopt);
        EXPECT_EQ(key.format(changed), text);
        EXPECT_EQ(formatted(changed), formatted(Config{}));
    }
}

TEST(Schema, NumericRangeEdges) {
    for (const Key& key : schema()) {
        if (key.type != ValueType::integer && key.type != ValueType::real) continue;
        SCOPED_TRACE(key.full_name());
        Config config;
        for (const double edge : {key.min, key.max}) {
            const std::string text = key.type == ValueType::integer
                                         ? std::to_string(static_cast<long long>(edge))
                                         : full_text(edge);
            EXPECT_EQ(key.set(config, text), std::nullopt) << text;
            EXPECT_EQ(std::stod(key.format(config)), edge);
        }
        const double step =
            key.type == ValueType::integer
                ? 1.0
                : std::max(1e-6, std::max(std::abs(key.min), std::abs(key.max)) * 1e-9);
        const auto outside = [&](double v) {
            return key.type == ValueType::integer ? std::to_string(static_cast<long long>(v))
                                                  : full_text(v);
        };
        const Config before = config;
        EXPECT_EQ(key.set(config, outside(key.min - step)), "value out of range");
        EXPECT_EQ(key.set(config, outside(key.max + step)), "value out of range");
        EXPECT_EQ(formatted(config), formatted(before));  // a rejected value changes nothing
        EXPECT_NE(key.set(config, "12abc"), std::nullopt);
        EXPECT_NE(key.set(config, ""), std::nullopt);
        // "min..max", each reading back as the exact bound.
        const std::string allowed = key.allowed();
        const auto dots = allowed.find("..");
        ASSERT_NE(dots, std::string::npos) << allowed;
        EXPECT_EQ(std::stod(allowed.substr(0, dots)), key.min) << allowed;
        EXPECT_EQ(std::stod(allowed.substr(dots + 2)), key.max) << allowed;
    }
}

TEST(Schema, RealsFormatToTheExactDouble) {
    // Shortest round trip: "0.02", not "0.020000000000000000"; all 17 digits when needed.
    for (const Key& key : schema()) {
        if (key.type != ValueType::real) continue;
        SCOPED_TRACE(key.full_name());
        Config config;
        for (const double v : {key.min + (key.max - key.min) / 3.0, key.min, key.max}) {
            ASSERT_EQ(key.set(config, full_text(v)), std::nullopt);
            EXPECT_EQ(std::stod(key.format(config)), v) << key.format(config);
        }
    }
    const Key* min_area = find_key("tracking", "min_area");
    Config config;
    ASSERT_EQ(min_area->set(config, "0.020000000000000000"), std::nullopt);
    EXPECT_EQ(min_area->format(config), "0.02");
}

TEST(Schema, EveryChoiceAcceptedAndAWrongWordRejected) {
    for (const Key& key : schema()) {
        if (key.type != ValueType::choice && key.type != ValueType::boolean) continue;
        SCOPED_TRACE(key.full_name());
        Config config;
        std::string joined;
        for (const auto choice : key.choices) {
            EXPECT_EQ(key.set(config, choice), std::nullopt);
            EXPECT_EQ(key.format(config), choice);
            if (!joined.empty()) joined += '|';
            joined += choice;
        }
        EXPECT_EQ(key.allowed(), joined);
        const std::string before = key.format(config);
        EXPECT_NE(key.set(config, "nope"), std::nullopt);
        EXPECT_NE(key.set(config, std::string(key.choices.front()) + " "), std::nullopt);
        EXPECT_EQ(key.format(config), before);
    }
}

TEST(Schema, BooleanSpellings) {
    const Key* key = find_key("tracking", "keep_still_target");
    ASSERT_NE(key, nullptr);
    Config config;
    for (const char* yes : {"true", "yes", "on", "1"}) {
        config.core.tracking.keep_still_target = false;
        EXPECT_EQ(key->set(config, yes), std::nullopt);
        EXPECT_TRUE(config.core.tracking.keep_still_target) << yes;
    }
    for (const char* no : {"false", "no", "off", "0"}) {
        config.core.tracking.keep_still_target = true;
        EXPECT_EQ(key->set(config, no), std::nullopt);
        EXPECT_FALSE(config.core.tracking.keep_still_target) << no;
    }
    EXPECT_EQ(key->set(config, "True"), "not a boolean");
}

std::string error_of(std::string_view assignment) {
    Config config;
    const auto before = formatted(config);
    try {
        apply_assignment(config, assignment);
    } catch (const ConfigError& error) {
        EXPECT_EQ(formatted(config), before) << "a failed assignment changed the config";
        return error.what();
    }
    return "(no error)";
}

TEST(ApplyAssignment, SetsTheField) {
    Config config;
    apply_assignment(config, "tracking.min_area=0.05");
    EXPECT_EQ(config.core.tracking.min_area, 0.05);
    apply_assignment(config, "estimator.method=iterative-ny-ray");
    EXPECT_EQ(config.core.estimator.kind, core::EstimatorKind::iterative_ny_ray);
    apply_assignment(config, "preprocess.edge_source=luma");
    EXPECT_EQ(config.core.preprocess.edge_source, core::EdgeSource::luma);
    apply_assignment(config, "estimator.rays=32");
    EXPECT_EQ(config.core.estimator.rays, 32);
}

TEST(ApplyAssignment, ExactMessages) {
    EXPECT_EQ(error_of("tracking.min_aera=0.1"),
              "--set tracking.min_aera=0.1: unknown key (did you mean tracking.min_area?)");
    EXPECT_EQ(error_of("track.min_area=0.1"),
              "--set track.min_area=0.1: unknown key (did you mean tracking.min_area?)");
    EXPECT_EQ(error_of("estimator.ray=8"),
              "--set estimator.ray=8: unknown key (did you mean estimator.rays?)");
    EXPECT_EQ(error_of("tracking.min_area"), "--set tracking.min_area: expected section.key=value");
    EXPECT_EQ(error_of("min_area=0.1"), "--set min_area=0.1: expected section.key=value");
    EXPECT_EQ(error_of("tracking.min_area=abc"),
              "--set tracking.min_area=abc: not a number (allowed: 0..1)");
    EXPECT_EQ(error_of("tracking.min_area=0.1=2"),
              "--set tracking.min_area=0.1=2: not a number (allowed: 0..1)");
    EXPECT_EQ(error_of("tracking.min_area=2"),
              "--set tracking.min_area=2: value out of range (allowed: 0..1)");
    EXPECT_EQ(error_of("estimator.rays=1.5"),
              "--set estimator.rays=1.5: not an integer (allowed: 3..256)");
    EXPECT_EQ(error_of("estimator.rays=2"),
              "--set estimator.rays=2: value out of range (allowed: 3..256)");
    EXPECT_EQ(error_of("tracking.keep_still_target=maybe"),
              "--set tracking.keep_still_target=maybe: not a boolean (allowed: true|false)");
    EXPECT_EQ(error_of("estimator.method=rays"),
              "--set estimator.method=rays: unknown value, did you mean ray? (allowed: "
              "ray|iterative-ray|iterative-ny-ray|raster)");
    EXPECT_EQ(error_of("output.ema_weight=1"),
              "--set output.ema_weight=1: value out of range (allowed: 0..0.999)");
}

TEST(CrossCheck, EachRuleHasItsMessage) {
    Config config;
    EXPECT_TRUE(cross_check(config).empty());
    ASSERT_TRUE(apply_preset(config, "paper"));
    EXPECT_TRUE(cross_check(config).empty());

    config = Config{};
    config.core.tracking.min_area = config.core.tracking.max_area;  // equal: not below it
    EXPECT_EQ(cross_check(config),
              std::vector<std::string>{"tracking.min_area must be below tracking.max_area"});
    config = Config{};
    config.core.tracking.search_threshold = 5000.0;
    config.core.tracking.idle_threshold = 5001.0;
    EXPECT_EQ(cross_check(config),
              std::vector<std::string>{"tracking.idle_threshold must not exceed "
                                       "tracking.search_threshold"});
    config.core.tracking.idle_threshold = 5000.0;  // equal is allowed
    EXPECT_TRUE(cross_check(config).empty());
    config.core.tracking.color_patch = 4;
    EXPECT_EQ(cross_check(config),
              std::vector<std::string>{"tracking.color_patch must be odd, so the square has "
                                       "a centre"});
    config = Config{};
    config.core.preprocess.work_height = 40;
    config.core.estimator.block_size = 41;
    EXPECT_EQ(cross_check(config),
              std::vector<std::string>{"estimator.block_size must fit in the working image"});
    config.core.estimator.block_size = 40;
    EXPECT_TRUE(cross_check(config).empty());
    config.core.tracking.min_area = 0.9;
    config.core.tracking.color_patch = 2;
    EXPECT_EQ(cross_check(config).size(), 2U);
}

TEST(CrossCheck, PointerRulesHaveTheirMessages) {
    using Problems = std::vector<std::string>;
    Config config;
    config.core.pointer.motion.active_left = 0.9;
    config.core.pointer.motion.active_right = 0.1;
    EXPECT_EQ(cross_check(config),
              Problems{"pointer.active_left must be below pointer.active_right"});
    config = Config{};
    config.core.pointer.motion.active_bottom = config.core.pointer.motion.active_top;
    EXPECT_EQ(cross_check(config),
              Problems{"pointer.active_top must be below pointer.active_bottom"});
    config = Config{};
    config.core.pointer.click.release_rise = config.core.pointer.click.press_rise;
    EXPECT_EQ(cross_check(config), Problems{"click.release_rise must be below click.press_rise, "
                                            "or a press releases at once"});
    config = Config{};
    config.core.pointer.click.start_rise = 0.3;
    EXPECT_EQ(cross_check(config), Problems{"click.start_rise must be below click.press_rise: a "
                                            "push begins before it presses"});
    config.core.pointer.motion.active_left = 1.0;  // every broken rule is reported
    EXPECT_EQ(cross_check(config).size(), 2U);
}

TEST(Ini, RoundTripsLineByLineThroughApplyAssignment) {
    Config source;
    for (const Key& key : schema()) {
        ASSERT_EQ(key.set(source, other_value(key)), std::nullopt) << key.full_name();
    }
    ASSERT_NE(formatted(source), formatted(Config{}));
    const std::string ini = to_ini(source);

    Config read;
    std::istringstream lines(ini);
    std::string line;
    std::string section;
    std::set<std::string> seen;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (line.front() == '[') {
            ASSERT_EQ(line.back(), ']') << line;
            section = line.substr(1, line.size() - 2);
            continue;
        }
        const auto equals = line.find(" = ");
        ASSERT_NE(equals, std::string::npos) << line;
        const std::string name = line.substr(0, equals);
        EXPECT_TRUE(seen.insert(section + "." + name).second) << "twice: " << name;
        ASSERT_NO_THROW(
            apply_assignment(read, section + "." + name + "=" + line.substr(equals + 3)))
            << line;
    }
    EXPECT_EQ(seen.size(), schema().size());
    EXPECT_EQ(formatted(read), formatted(source));
    // Each key is documented with its range and default.
    const std::string min_area_default = find_key("tracking", "min_area")->format(Config{});
    EXPECT_NE(ini.find("# smallest target area, fraction of the frame\n"
                       "# allowed: 0..1, default: " +
                       min_area_default +
                       "\nmin_area = " + find_key("tracking", "min_area")->format(source) + "\n"),
              std::string::npos);
}

TEST(Presets, PaperSwitchesEveryDeviationBack) {
    Config config;
    config.core.estimator.rays = 99;
    ASSERT_TRUE(apply_preset(config, "paper"));
    EXPECT_EQ(config.core.preprocess.edge_source, core::EdgeSource::luma);
    EXPECT_EQ(config.core.estimator.area_mode, core::AreaMode::blocks);
    EXPECT_FALSE(config.core.tracking.keep_still_target);
    EXPECT_FALSE(config.core.tracking.recover_small);
    EXPECT_EQ(config.core.tracking.search_weighting, core::SearchWeighting::all);
    EXPECT_EQ(config.core.output.smoothing, core::SmoothingKind::ema);
    EXPECT_EQ(config.core.estimator.rays, 16);  // the preset is a whole configuration
    EXPECT_EQ(config.core.estimator.kind, core::EstimatorKind::raster);
    // The paper's numbers (4.1, 4.2), whatever the measured defaults are.
    EXPECT_EQ(config.core.preprocess.edge_threshold, 128);
    EXPECT_EQ(config.core.tracking.search_threshold, 57600.0);
    EXPECT_EQ(config.core.tracking.idle_threshold, 4800.0);
    EXPECT_EQ(config.core.tracking.min_area, 0.02);
    EXPECT_EQ(config.core.tracking.max_area, 0.60);
    EXPECT_EQ(config.core.tracking.color_tolerance, 90);
    EXPECT_EQ(config.core.tracking.startup_seconds, 2.0);
    EXPECT_EQ(config.core.output.ema_weight, 0.9);
    EXPECT_EQ(config.core.output.ema_frame_rate, 0.0);  // once a frame (4.3)

    const auto paper = formatted(config);
    EXPECT_FALSE(apply_preset(config, "nope"));
    EXPECT_EQ(formatted(config), paper);
    EXPECT_TRUE(apply_preset(config, "default"));
    EXPECT_EQ(formatted(config), formatted(Config{}));
    EXPECT_NE(formatted(config), paper);
}

}  // namespace
}  // namespace raypoint::config
