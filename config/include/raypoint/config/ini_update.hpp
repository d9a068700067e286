// SPDX-License-Identifier: MIT
#pragma once
// Writing settings back into a user's INI file (raypoint preview's save key, raypoint setup):
// each key's line is changed in place, so the file keeps its comments, its order and every
// setting nobody changed; a key the file lacks goes at the end of its section (the section is
// added at the end when the file has none).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "raypoint/config/config.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::config {

// `text` with each of `keys` set to its value in `config` (Key::format). A comment after a
// value ("rays = 8  # eight") stays.
std::string update_ini_text(std::string_view text, const Config& config,
                            std::span<const Key* const> keys);

// update_ini_text on the file at `path` (a new file when there is none), checked by the schema
// before it replaces the old one (written beside it, then renamed). Throws ConfigError naming
// the path, the call and the reason.
void write_ini_values(const std::filesystem::path& path, const Config& config,
                      std::span<const Key* const> keys);

}  // namespace raypoint::config
