// SPDX-License-Identifier: MIT
// Writing settings back into an INI file (preview's save key, setup): values change in place,
// comments and order stay, missing keys and sections are added, the result reads back.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/ini_update.hpp"

namespace raypoint::config {
namespace {

std::vector<const Key*> keys(std::initializer_list<std::pair<const char*, const char*>> names) {
    std::vector<const Key*> out;
    for (const auto& [section, name] : names)
        out.push_back(find_key(section, name));
    return out;
}

TEST(IniUpdate, ChangesValuesInPlaceKeepingCommentsAndOrder) {
    const std::string text =
        "# my raypoint settings\n"
        "[tracking]\n"
        "; the room is busy\n"
        "min_area = 0.02   # found by trying\n"
        "max_area=0.5\n"
        "\n"
        "[preprocess]\n"
        "edge_threshold = 120\n"
        "filter_radius = 4\n";
    Config config;
    config.core.tracking.min_area = 0.015;
    config.core.preprocess.edge_threshold = 80;
    const auto wanted = keys({{"tracking", "min_area"}, {"preprocess", "edge_threshold"}});
    EXPECT_EQ(update_ini_text(text, config, wanted),
              "# my raypoint settings\n"
              "[tracking]\n"
              "; the room is busy\n"
              "min_area = 0.015 # found by trying\n"
              "max_area=0.5\n"
              "\n"
              "[preprocess]\n"
              "edge_threshold = 80\n"
              "filter_radius = 4\n");
}

TEST(IniUpdate, AddsMissingKeysToTheirSectionAndMissingSectionsAtTheEnd) {
    const std::string text =
        "[tracking]\n"
        "min_area = 0.02\n"
        "\n"
        "[pointer]\n"
        "gain = 2000\n";
    Config config;
    config.core.tracking.max_area = 0.4;
    config.core.pointer.click.press_rise = 0.15;
    const auto wanted = keys({{"tracking", "max_area"}, {"click", "press_rise"}});
    const std::string updated = update_ini_text(text, config, wanted);
    EXPECT_EQ(updated,
              "[tracking]\n"
              "min_area = 0.02\n"
              "max_area = 0.4\n"
              "\n"
              "[pointer]\n"
              "gain = 2000\n"
              "\n"
              "[click]\n"
              "press_rise = 0.15\n");
    const IniFile parsed = parse_ini(updated, "t.ini");
    EXPECT_TRUE(parsed.errors.empty());
    EXPECT_EQ(parsed.settings.size(), 4U);
}

TEST(IniUpdate, WritesAFileThatLoadsBackWithTheNewValues) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("raypoint-ini-update-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / "raypoint.ini";
    std::ofstream(path) << "# keep me\n[click]\nrelease_rise = 0.08\n";
    Config config;
    config.core.pointer.click.press_rise = 0.3;
    config.core.pointer.click.release_rise = 0.12;
    write_ini_values(path, config, keys({{"click", "press_rise"}, {"click", "release_rise"}}));
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "# keep me\n[click]\nrelease_rise = 0.12\npress_rise = 0.3\n");
    const Config loaded = load_config(path);
    EXPECT_DOUBLE_EQ(loaded.core.pointer.click.press_rise, 0.3);
    EXPECT_DOUBLE_EQ(loaded.core.pointer.click.release_rise, 0.12);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace raypoint::config
