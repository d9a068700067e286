// SPDX-License-Identifier: MIT
// The command line over the file (daemon/src/settings_options.cpp): preset, then --config FILE,
// then --estimator and --set in order; the cross-checks after all of them.

#include <string>

#include <gtest/gtest.h>

#include "ini_testing.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"

namespace raypoint::daemon {
namespace {

using config::testing::TempDir;

config::Config parse(std::vector<std::string_view> args,
                     const std::optional<std::filesystem::path>& default_file = std::nullopt) {
    std::vector<std::string_view> rest;
    const auto config = parse_settings_options(args, rest, default_file);
    EXPECT_EQ(rest, std::vector<std::string_view>{});
    return config;
}

std::vector<std::string> errors_of(std::vector<std::string_view> args) {
    try {
        parse(args);
    } catch (const config::InvalidConfig& invalid) {
        return invalid.errors();
    }
    return {};
}

class IniOptions : public ::testing::Test {
  protected:
    TempDir dir_;
    const std::string file_ =
        dir_.write("raypoint.ini",
                   "[general]\npreset = paper\n[estimator]\nrays = 8\nmethod = ray\n")
            .string();
};

TEST_F(IniOptions, FileThenCommandLine) {
    const auto from_file = parse({"--config", file_});
    EXPECT_EQ(from_file.core.estimator.rays, 8);
    EXPECT_EQ(from_file.core.estimator.kind, core::EstimatorKind::ray);
    EXPECT_EQ(from_file.core.preprocess.edge_threshold, 128);  // the file's preset

    // --set and --estimator win over the file, wherever they stand.
    const auto overridden =
        parse({"--set", "estimator.rays=9", "--config", file_, "--estimator", "raster"});
    EXPECT_EQ(overridden.core.estimator.rays, 9);
    EXPECT_EQ(overridden.core.estimator.kind, core::EstimatorKind::raster);
    EXPECT_EQ(overridden.core.preprocess.edge_threshold, 128);
}

TEST_F(IniOptions, PresetOptionReplacesTheFilesPresetNotItsKeys) {
    const auto config = parse({"--config", file_, "--preset", "default"});
    EXPECT_EQ(config.core.preprocess.edge_threshold, 96);
    EXPECT_EQ(config.core.estimator.rays, 8);
}

TEST_F(IniOptions, DefaultFileOnlyWithoutConfigOption) {
    const auto other = dir_.write("other.ini", "[estimator]\nrays = 12\n");
    EXPECT_EQ(parse({}, other).core.estimator.rays, 12);
    EXPECT_EQ(parse({"--config", file_}, other).core.estimator.rays, 8);
    EXPECT_EQ(parse({}).core.estimator.rays, config::Config{}.core.estimator.rays);
}

TEST_F(IniOptions, CrossChecksComeAfterTheCommandLine) {
    const auto crossed = dir_.write("crossed.ini", "[tracking]\nmin_area = 0.7\n").string();
    EXPECT_EQ(errors_of({"--config", crossed}),
              std::vector<std::string>{"tracking.min_area must be below tracking.max_area"});
    EXPECT_EQ(parse({"--config", crossed, "--set", "tracking.max_area=0.8"}).core.tracking.min_area,
              0.7);
}

TEST_F(IniOptions, EveryFileErrorAtOnce) {
    const auto bad = dir_.write("bad.ini", "[estimator]\nrays = 1\nrayz = 8\n").string();
    EXPECT_EQ(errors_of({"--config", bad, "--set", "estimator.rays=9"}),
              (std::vector<std::string>{
                  bad + ":2: [estimator] rays: value out of range (allowed: 3..256)",
                  bad + ":3: [estimator] rayz: unknown key (did you mean rays?)"}));
    EXPECT_EQ(errors_of({"--config", dir_.path().string() + "/missing.ini"}),
              std::vector<std::string>{dir_.path().string() +
                                       "/missing.ini: cannot open: No such file or directory"});
}

TEST_F(IniOptions, UsageErrors) {
    EXPECT_THROW(parse({"--config", file_, "--config", file_}), UsageError);
    EXPECT_THROW(parse({"--config"}), UsageError);
    EXPECT_THROW(parse({"--preset", "papr", "--config", file_}), UsageError);
    std::vector<std::string_view> rest;
    const std::vector<std::string_view> args{"clip.mp4", "--config", file_, "--fps", "30"};
    parse_settings_options(args, rest);
    EXPECT_EQ(rest, (std::vector<std::string_view>{"clip.mp4", "--fps", "30"}));
}

}  // namespace
}  // namespace raypoint::daemon
