// SPDX-License-Identifier: MIT
// Configuration files on disk: read errors, the size bound, load_config's all-or-nothing answer,
// the XDG search path, the print-config round trip and the shipped packaging/raypoint.ini.

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "ini_testing.hpp"
#include "raypoint/config/config_paths.hpp"

namespace raypoint::config {
namespace {

using testing::formatted;
using testing::ScopedEnv;
using testing::TempDir;
using Errors = std::vector<std::string>;

Errors load_errors(const std::filesystem::path& path) {
    try {
        load_config(path);
    } catch (const InvalidConfig& invalid) {
        return invalid.errors();
    }
    return {};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(IniFiles, ReadErrorsNameThePathAndTheReason) {
    const TempDir dir;
    const auto missing = dir.path() / "missing.ini";
    EXPECT_EQ(load_errors(missing),
              Errors{missing.string() + ": cannot open: No such file or directory"});
    EXPECT_EQ(load_errors(dir.path()),
              Errors{dir.path().string() + ": cannot read: Is a directory"});
}

TEST(IniFiles, UnreadableFileSaysPermissionDenied) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
    const TempDir dir;
    const auto path = dir.write("locked.ini", "[estimator]\n");
    std::filesystem::permissions(path, std::filesystem::perms::none);
    EXPECT_EQ(load_errors(path), Errors{path.string() + ": cannot open: Permission denied"});
}

TEST(IniFiles, LoadConfigGivesAValidConfigOrEveryError) {
    const TempDir dir;
    const auto good = dir.write("good.ini", "[general]\npreset = paper\n[estimator]\nrays = 8\n");
    const Config config = load_config(good);
    EXPECT_EQ(config.core.estimator.rays, 8);
    EXPECT_EQ(config.core.preprocess.edge_threshold, 128);
    EXPECT_EQ(load_config(good, "default").core.preprocess.edge_threshold, 96);

    // Cross-checks come after the file, at the line of the last key they name; each key alone
    // is in range.
    const auto crossed = dir.write("crossed.ini", "[tracking]\nmin_area = 0.7\ncolor_patch = 4\n");
    EXPECT_EQ(load_errors(crossed),
              (Errors{crossed.string() + ":2: tracking.min_area must be below tracking.max_area",
                      crossed.string() + ":3: tracking.color_patch must be odd, so the square has "
                                         "a centre"}));
    const auto pair = dir.write("pair.ini", "[tracking]\nmax_area = 0.2\nmin_area = 0.3\n");
    EXPECT_EQ(load_errors(pair),
              Errors{pair.string() + ":3: tracking.min_area must be below tracking.max_area"});
    // One key of the pair from the preset: the line of the one the file set.
    const auto preset_only = dir.write("preset.ini", "[pointer]\nactive_left = 0.99\n");
    EXPECT_EQ(load_errors(preset_only),
              Errors{preset_only.string() +
                     ":2: pointer.active_left must be below pointer.active_right"});
    // ...but only when every line is right: a half-applied file would blame the wrong keys.
    const auto both = dir.write("both.ini", "[tracking]\nmin_area = 0.7\nmax_area = 2\n");
    EXPECT_EQ(load_errors(both),
              Errors{both.string() + ":3: [tracking] max_area: value out of range (allowed: "
                                     "0..1)"});
    try {
        load_config(both);
        ADD_FAILURE() << "no exception";
    } catch (const ConfigError& error) {  // callers may catch the base
        EXPECT_EQ(std::string(error.what()), load_errors(both).front());
    }
}

TEST(IniFiles, HugeFilesAreBoundedWork) {
    const TempDir dir;
    const auto start = std::chrono::steady_clock::now();
    // 10 MB of comments on disk: refused after reading 1 MiB.
    std::string comments;
    while (comments.size() < 10'000'000)
        comments += "# a comment line, as a log file or a mistaken path would have\n";
    const auto huge = dir.write("huge.ini", comments);
    EXPECT_EQ(load_errors(huge),
              Errors{huge.string() + ": larger than 1 MiB, which no raypoint configuration is"});
    // Just under the limit is read, whatever the lines are.
    const auto at_limit = dir.write("limit.ini", comments.substr(0, max_file_bytes));
    EXPECT_EQ(load_errors(at_limit), Errors{});
    // The same 10 MB as text, and 100k lines of nonsense: linear, and errors stop at the cap.
    EXPECT_EQ(parse_ini(comments, "t.ini").errors, Errors{});
    std::string nonsense;
    for (int i = 0; i < 100'000; ++i)
        nonsense += "nonsense\n";
    const auto errors = parse_ini(nonsense, "t.ini").errors;
    ASSERT_EQ(errors.size(), max_errors + 1);
    EXPECT_EQ(errors.back(), "t.ini:100: stopped after 100 errors");
    EXPECT_LT(seconds_since(start), 2.0);
}

TEST(IniFiles, SearchPathFollowsXdg) {
    const TempDir dir;
    const auto home = dir.path() / "home";
    const auto config_home = dir.path() / "config-home";
    const auto first = dir.path() / "first";
    const auto second = dir.path() / "second";
    const ScopedEnv home_env("HOME", home.string());
    const ScopedEnv config_home_env("XDG_CONFIG_HOME", config_home.string());
    const ScopedEnv dirs_env("XDG_CONFIG_DIRS",
                             first.string() + "::relative/dir:" + second.string());
    const auto in = [](const std::filesystem::path& base) {
        return base / "raypoint" / "raypoint.ini";
    };
    EXPECT_EQ(config_search_path(),
              (std::vector<std::filesystem::path>{in(config_home), in(first), in(second)}));

    EXPECT_EQ(find_config_file(), std::nullopt);
    dir.write("second/raypoint/raypoint.ini", "");
    EXPECT_EQ(find_config_file(), in(second));
    dir.write("first/raypoint/raypoint.ini", "");
    EXPECT_EQ(find_config_file(), in(first));
    dir.write("config-home/raypoint/raypoint.ini", "");
    EXPECT_EQ(find_config_file(), in(config_home));
    dir.write("home/.config/raypoint/raypoint.ini", "");
    EXPECT_EQ(find_config_file(), in(config_home));  // XDG_CONFIG_HOME replaces ~/.config
}

TEST(IniFiles, SearchPathDefaults) {
    const ScopedEnv home_env("HOME", "/home/someone");
    {
        const ScopedEnv config_home_env("XDG_CONFIG_HOME", std::nullopt);
        const ScopedEnv dirs_env("XDG_CONFIG_DIRS", std::nullopt);
        EXPECT_EQ(config_search_path(),
                  (std::vector<std::filesystem::path>{"/home/someone/.config/raypoint/raypoint.ini",
                                                      "/etc/xdg/raypoint/raypoint.ini"}));
    }
    // Relative and empty values are ignored, as the specification says.
    const ScopedEnv config_home_env("XDG_CONFIG_HOME", "relative");
    const ScopedEnv dirs_env("XDG_CONFIG_DIRS", "");
    EXPECT_EQ(config_search_path(),
              (std::vector<std::filesystem::path>{"/home/someone/.config/raypoint/raypoint.ini",
                                                  "/etc/xdg/raypoint/raypoint.ini"}));
}

TEST(IniFiles, PrintConfigOutputRoundTrips) {
    // Every key changed from its default, so a key the file misses shows.
    Config changed;
    for (const Key& key : schema()) {
        std::vector<std::string> candidates;
        if (key.type == ValueType::integer || key.type == ValueType::real) {
            for (const double value : {key.min + (key.max - key.min) / 3.0, key.max, key.min}) {
                char text[64];
                std::snprintf(text, sizeof text, "%.17g",
                              key.type == ValueType::integer ? std::floor(value) : value);
                candidates.emplace_back(text);
            }
        } else if (key.type == ValueType::device) {
            candidates = {"/dev/video2", "auto"};
        } else {
            candidates.assign(key.choices.begin(), key.choices.end());
        }
        for (const auto& value : candidates) {
            if (key.format(changed) != key.format(Config{})) break;
            ASSERT_EQ(key.set(changed, value), std::nullopt) << key.full_name() << value;
        }
        EXPECT_NE(key.format(changed), key.format(Config{})) << key.full_name();
    }
    Config paper;
    ASSERT_TRUE(apply_preset(paper, "paper"));
    for (const Config& config : {Config{}, paper, changed}) {
        const auto loaded = testing::load_text(to_ini(config));
        EXPECT_EQ(loaded.errors, Errors{});
        EXPECT_EQ(loaded.file.settings.size(), schema().size());
        EXPECT_EQ(formatted(loaded.config), formatted(config));
    }
}

TEST(IniFiles, ShippedExampleIsValidAndAllDefaults) {
    const std::filesystem::path shipped = RAYPOINT_SOURCE_DIR "/packaging/raypoint.ini";
    EXPECT_EQ(load_errors(shipped), Errors{});
    const Config loaded = load_config(shipped);
    for (const Key& key : schema()) {
        EXPECT_EQ(key.format(loaded), key.format(Config{}))
            << key.full_name() << ": regenerate with raypoint print-config --defaults > "
            << "packaging/raypoint.ini";
    }
    EXPECT_EQ(read_ini_file(shipped).settings.size(), schema().size());
}

}  // namespace
}  // namespace raypoint::config
