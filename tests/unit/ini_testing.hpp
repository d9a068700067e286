// SPDX-License-Identifier: MIT
#pragma once
// Helpers for the configuration-file tests: field-by-field comparison through the schema, a
// temporary directory, and environment variables restored after the test.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::config::testing {

// Every key's formatted value. Reals format to the shortest text that reads back exactly, so
// equal lists mean equal configurations.
inline std::vector<std::string> formatted(const Config& config) {
    std::vector<std::string> values;
    for (const Key& key : schema())
        values.push_back(key.full_name() + "=" + key.format(config));
    return values;
}

// parse_ini, then config_from_file: the errors of both, in order.
struct Loaded {
    IniFile file;
    Config config;
    std::vector<std::string> errors;
};
inline Loaded load_text(std::string_view text,
                        std::optional<std::string_view> preset = std::nullopt) {
    Loaded loaded{parse_ini(text, "t.ini"), {}, {}};
    loaded.errors = loaded.file.errors;
    loaded.config = config_from_file(loaded.file, preset, loaded.errors);
    return loaded;
}

class TempDir {
  public:
    TempDir() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "raypoint-test-XXXXXX").string();
        if (::mkdtemp(pattern.data()) == nullptr) ADD_FAILURE() << "mkdtemp failed";
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

    // Writes `text` to `relative`, creating its directories; returns the full path.
    std::filesystem::path write(const std::filesystem::path& relative,
                                std::string_view text) const {
        const auto full = path_ / relative;
        std::filesystem::create_directories(full.parent_path());
        std::ofstream(full, std::ios::binary) << text;
        return full;
    }

  private:
    std::filesystem::path path_;
};

// Sets (or unsets, with nullopt) an environment variable for the scope of the object.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, std::optional<std::string> value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value) {
            ::setenv(name, value->c_str(), 1);
        } else {
            ::unsetenv(name);
        }
    }
    ~ScopedEnv() {
        if (old_) {
            ::setenv(name_, old_->c_str(), 1);
        } else {
            ::unsetenv(name_);
        }
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace raypoint::config::testing
