// SPDX-License-Identifier: MIT
#pragma once
// Configuration files (docs/configuration.md): INI text checked against the schema with
// "file:line:" messages, and the whole load (preset, file, cross-checks) that gives either a
// valid Config or every error at once, so a reload can keep the running config on error.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raypoint/config/config.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::config {

// Every problem of one configuration, each a complete line ready to print ("raypoint.ini:7:
// [estimator] rays: value out of range (allowed: 3..256)"). what() is the lines joined by '\n'.
class InvalidConfig : public ConfigError {
  public:
    explicit InvalidConfig(std::vector<std::string> errors);
    const std::vector<std::string>& errors() const noexcept { return errors_; }

  private:
    std::vector<std::string> errors_;
};

// Bounds on the work any input can cause (a log file passed by mistake, /dev/zero): a raypoint
// configuration is a few kB, and past a hundred errors the file is not one.
inline constexpr std::size_t max_file_bytes = std::size_t{1} << 20;
inline constexpr std::size_t max_errors = 100;

// The INI section the loader handles itself: `[general] preset = default|paper`. It is not a
// setting of the schema because it picks the values the other keys start from.
inline constexpr std::string_view general_section = "general";
inline constexpr std::string_view preset_key = "preset";
inline constexpr std::string_view preset_names = "default|paper";  // apply_preset's

// One "key = value" line naming a key of the schema, with the value read from it.
struct IniSetting {
    const Key* key = nullptr;
    Value value;  // what key->parse() read; key->assign() stores it
    int line = 0;
};

// A configuration file checked line by line: known sections and keys, each key once, values in
// range. What involves several keys (cross_check) needs the whole Config and comes later.
struct IniFile {
    std::string name;  // the path as given, the start of every message
    std::optional<std::string> preset;
    std::vector<IniSetting> settings;  // in file order
    std::vector<std::string> errors;   // at most max_errors + 1 (the last says where it stopped)
};

// Parses INI text. `name` is used in the messages only.
IniFile parse_ini(std::string_view text, std::string name);

// Reads and parses a file. Throws InvalidConfig with one message when it cannot be read:
// "path: cannot open: No such file or directory", or when it is larger than max_file_bytes.
IniFile read_ini_file(const std::filesystem::path& path);

// The preset (`preset`, else the file's [general] preset, else "default"), then every setting of
// the file. Appends a message for an unknown `preset`; no cross-checks, so that the command line
// can still change what the file set.
Config config_from_file(const IniFile& file, std::optional<std::string_view> preset,
                        std::vector<std::string>& errors);

// read_ini_file, config_from_file, cross_check: a complete valid Config, or InvalidConfig with
// every error of the file ("path: tracking.min_area must be below tracking.max_area" for the
// cross-checks).
Config load_config(const std::filesystem::path& path,
                   std::optional<std::string_view> preset = std::nullopt);

}  // namespace raypoint::config
