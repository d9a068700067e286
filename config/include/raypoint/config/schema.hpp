// SPDX-License-Identifier: MIT
#pragma once
// The one schema of every setting (docs/design.md rule 4): section, key, type, default, range and
// a one-line doc. Parsing (--set, INI), validation, print-config and the docs all come from it.

#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "raypoint/config/config.hpp"

namespace raypoint::config {

// device: `auto` or a path under /dev (a camera).
enum class ValueType { integer, real, boolean, choice, device };

// A choice key's value: the position of its text in Key::choices.
struct ChoiceIndex {
    std::size_t index = 0;
};
// A value read from text by Key::parse, kept so that it is applied without being read again:
// integer, real, boolean, choice, device (its path).
using Value = std::variant<int, double, bool, ChoiceIndex, std::string>;

struct Key {
    std::string_view section;
    std::string_view name;
    ValueType type = ValueType::integer;
    double min = 0.0;  // integer and real
    double max = 0.0;
    std::vector<std::string_view> choices;  // choice
    std::string_view doc;
    std::function<std::string(const Config&)> format;
    // Reads a value from text into `value`; returns the reason when the text is not a valid one.
    std::function<std::optional<std::string>(std::string_view text, Value& value)> parse;
    // Stores a value parse() gave into the configuration.
    std::function<void(Config&, const Value&)> assign;

    std::string full_name() const;  // "section.name"
    std::string allowed() const;    // "16..256", "true|false", "ray|raster"
    // parse(), then assign() when the text is valid; returns parse()'s reason otherwise.
    std::optional<std::string> set(Config& config, std::string_view text) const;
};

const std::vector<Key>& schema();
const Key* find_key(std::string_view section, std::string_view name) noexcept;
// The valid "section.name" closest to `wanted` by edit distance, for "did you mean"; empty when
// none is close enough to be what was meant (similar()).
std::string nearest_key(std::string_view wanted);
// Levenshtein distance: the edits (insert, delete, replace a character) that turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);
// Whether `distance` edits to a name of `length` characters is a typo rather than another word:
// at most a third of the letters, plus one (a swap costs two edits, "min_aera" is min_area).
// Garbage then gets no suggestion instead of a nonsense one.
constexpr bool similar(std::size_t distance, std::size_t length) noexcept {
    return distance * 3 <= length + 3;
}
// " (did you mean X?)" for a non-empty `suggestion`, else " (" + `otherwise` + ")".
std::string did_you_mean(const std::string& suggestion, std::string_view otherwise);
// The section closest to `wanted` among the schema's sections and `extra` ones (sections a reader
// handles itself, like the INI file's [general]), for "did you mean"; empty when none is similar.
std::string nearest_section(std::string_view wanted, std::span<const std::string_view> extra = {});

// A setting that cannot be applied. The message is complete and ready to print.
class ConfigError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Applies "section.key=value" (the --set option). Throws ConfigError:
// "--set tracking.min_area=2: value out of range (allowed: 0..1)".
void apply_assignment(Config& config, std::string_view assignment);

// Rules that involve more than one key (min_area < max_area, ...): one message each.
std::vector<std::string> cross_check(const Config& config);

// The configuration as a valid INI file with each key's doc and range as comments.
std::string to_ini(const Config& config);

}  // namespace raypoint::config
