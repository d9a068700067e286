// SPDX-License-Identifier: MIT
// INI syntax through inih, with the line numbers inih does not give.
//
// Debian's libinih is built without INI_HANDLER_LINENO, and the handler's signature is fixed when
// the library is built, so the handler cannot be told its line. But inih pulls lines through a
// reader callback and calls the handler for a line before it asks for the next one: the number of
// lines our reader has handed out is the handler's line. The reader also sees every line before
// inih does, which lets it report what inih only counts (it returns the first bad line): every
// malformed line, and headers of unknown sections even when no key follows. It hands inih a
// normalised line: no leading whitespace (inih would take an indented line for the continuation
// of the previous value), no comment, a header's name trimmed.

#include <ini.h>

#include <cstring>
#include <map>
#include <string>

#include "raypoint/config/ini_file.hpp"

namespace raypoint::config {
namespace {

constexpr std::string_view utf8_bom = "\xEF\xBB\xBF";
constexpr std::size_t shown_chars = 60;  // of a bad line, in its message

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && is_space(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && is_space(text.back()))
        text.remove_suffix(1);
    return text;
}

// Built by appending: on `"\"" + std::string(...)` GCC 12 at -O2 and above gives a false
// -Wrestrict warning.
std::string shown(std::string_view text) {
    std::string quoted(1, '"');
    quoted.append(text.substr(0, shown_chars));
    if (text.size() > shown_chars) quoted.append("...");
    quoted.push_back('"');
    return quoted;
}

// A comment after a value starts at ';' or '#' after whitespace ("rays = 8  # eight"). inih alone
// knows only " ;" (INI_INLINE_COMMENT_PREFIXES), and no value of the schema contains either.
std::string_view without_comment(std::string_view line) {
    for (std::size_t i = 1; i < line.size(); ++i) {
        if ((line[i] == ';' || line[i] == '#') && is_space(line[i - 1])) {
            return trim(line.substr(0, i));
        }
    }
    return line;
}

bool is_section(std::string_view name) {
    if (name == general_section) return true;
    for (const Key& key : schema()) {
        if (key.section == name) return true;
    }
    return false;
}

// The key meant by `name` in `section`, as "min_area" when it is in `section` and as
// "[tracking] min_area" when not. The name is what people mistype, so it is compared alone; the
// right name in the wrong section costs one edit more than a typo in the right one.
std::string suggestion(std::string_view section, std::string_view name) {
    std::string_view best_section;
    std::string_view best_name;
    std::size_t best_distance = SIZE_MAX;
    const auto consider = [&](std::string_view key_section, std::string_view key_name) {
        const std::size_t distance =
            edit_distance(name, key_name) + (section.empty() || key_section == section ? 0 : 1);
        if (distance < best_distance) {
            best_distance = distance;
            best_section = key_section;
            best_name = key_name;
        }
    };
    for (const Key& key : schema())
        consider(key.section, key.name);
    consider(general_section, preset_key);
    if (!similar(best_distance, name.size())) return {};
    if (best_section == section) return std::string(best_name);
    std::string named(1, '[');  // appended: see shown()
    named.append(best_section).append("] ").append(best_name);
    return named;
}

class Parser {
  public:
    Parser(std::string_view text, IniFile& file) : rest_(text), file_(file) {}

    void run() {
        const int result = ini_parse_stream(&Parser::read_line, this, &Parser::handle, this);
        finish_line();
        // Every line inih can reject is one we have reported; this is for a future inih.
        if (result != 0 && file_.errors.empty()) {
            add_error(file_.name + ":" + std::to_string(result) + ": not understood by inih");
        }
    }

  private:
    enum class SectionState { none, known, unknown };

    static char* read_line(char* buffer, int size, void* self) {
        return static_cast<Parser*>(self)->next_line(buffer, static_cast<std::size_t>(size));
    }
    static int handle(void* self, const char* section, const char* name, const char* value) {
        static_cast<Parser*>(self)->setting(section, name, value);
        return 1;  // errors are ours to collect; 0 would only make inih remember the line
    }

    std::string at_line() const { return file_.name + ":" + std::to_string(line_) + ": "; }

    void add_error(std::string message) {
        if (stopped_) return;
        file_.errors.push_back(std::move(message));
        if (file_.errors.size() == max_errors) {
            file_.errors.push_back(at_line() + "stopped after " + std::to_string(max_errors) +
                                   " errors");
            stopped_ = true;
        }
    }

    // The previous line was handed to inih as "key = value" but inih found no '=' in it.
    void finish_line() {
        if (key_line_ && !handled_) {
            add_error(at_line() + "expected \"key = value\", \"[section]\" or a comment, got " +
                      shown(key_text_));
        }
        key_line_ = false;
    }

    char* next_line(char* buffer, std::size_t size) {
        finish_line();
        if (stopped_ || rest_.empty() || size < 3) return nullptr;
        const auto newline = rest_.find('\n');
        std::string_view line = rest_.substr(0, newline);
        rest_ = newline == std::string_view::npos ? std::string_view() : rest_.substr(newline + 1);
        ++line_;
        if (line_ == 1 && line.starts_with(utf8_bom)) line.remove_prefix(utf8_bom.size());
        const std::string handed = normalise(trim(line), size - 2);
        std::memcpy(buffer, handed.data(), handed.size());
        buffer[handed.size()] = '\n';
        buffer[handed.size() + 1] = '\0';
        return buffer;
    }

    // The line inih gets for `line` (at most `room` characters): empty when there is nothing
    // for it to do or the line is wrong already.
    std::string normalise(std::string_view line, std::size_t room) {
        if (line.empty() || line.front() == ';' || line.front() == '#') return {};
        if (line.find('\0') != std::string_view::npos) {
            add_error(at_line() + "contains a NUL byte (not a text file?)");
            return {};
        }
        if (line.front() == '[') return header(line);
        const std::string_view setting = without_comment(line);
        if (setting.size() > room) {
            add_error(at_line() + "line too long (a setting has at most " + std::to_string(room) +
                      " characters)");
            return {};
        }
        key_line_ = true;
        handled_ = false;
        key_text_ = setting;
        return std::string(setting);
    }

    std::string header(std::string_view line) {
        const auto close = line.find(']');
        if (close == std::string_view::npos) {
            add_error(at_line() + "unterminated section header " + shown(line) + " (no \"]\")");
            section_ = SectionState::unknown;
            return {};
        }
        const std::string name(trim(line.substr(1, close - 1)));
        const std::string_view after = trim(line.substr(close + 1));
        if (!after.empty() && after.front() != ';' && after.front() != '#') {
            add_error(at_line() + "[" + name + "]: text after the section header: " + shown(after));
        }
        if (!is_section(name)) {
            const std::string_view extra[] = {general_section};
            const std::string near = nearest_section(name, extra);
            add_error(at_line() + "[" + name + "]: unknown section" +
                      did_you_mean(near.empty() ? near : "[" + near + "]",
                                   "raypoint print-config lists every section"));
            section_ = SectionState::unknown;
            return {};
        }
        section_ = SectionState::known;
        section_name_ = name;
        return "[" + name + "]";
    }

    void setting(const char* /*section*/, const char* name_text, const char* value_text) {
        handled_ = true;
        const std::string_view name = name_text;
        if (name.empty()) {
            add_error(at_line() + "missing key name: " + shown(key_text_));
            return;
        }
        switch (section_) {
            case SectionState::none:
                add_error(
                    at_line() + std::string(name) + ": key before the first [section]" +
                    did_you_mean(suggestion("", name), "raypoint print-config lists every key"));
                return;
            case SectionState::unknown:
                return;  // the header's error says it all
            case SectionState::known:
                break;
        }
        // The section inih passes is the header we handed it, so ours is the same.
        const std::string where = at_line() + "[" + section_name_ + "] " + std::string(name) + ": ";
        const Key* key = section_name_ == general_section ? nullptr : find_key(section_name_, name);
        const bool is_preset = section_name_ == general_section && name == preset_key;
        if (key == nullptr && !is_preset) {
            add_error(where + "unknown key" +
                      did_you_mean(suggestion(section_name_, name),
                                   "raypoint print-config lists every key"));
            return;
        }
        const auto [first, inserted] =
            first_line_.try_emplace(section_name_ + "." + std::string(name), line_);
        if (!inserted) {
            add_error(where + "duplicate key (first on line " + std::to_string(first->second) +
                      ")");
            return;
        }
        if (is_preset) {
            Config scratch;
            if (!apply_preset(scratch, value_text)) {
                add_error(where + "unknown preset (allowed: " + std::string(preset_names) + ")");
                return;
            }
            file_.preset = value_text;
            return;
        }
        // Whether a value is valid does not depend on the others, so it is checked here, where
        // its error comes out in line order with the rest, and the value read is kept.
        Value value;
        if (const auto reason = key->parse(value_text, value)) {
            add_error(where + *reason + " (allowed: " + key->allowed() + ")");
            return;
        }
        file_.settings.push_back(IniSetting{key, std::move(value), line_});
    }

    std::string_view rest_;
    IniFile& file_;
    int line_ = 0;  // the line inih is working on
    bool stopped_ = false;
    SectionState section_ = SectionState::none;
    std::string section_name_;
    bool key_line_ = false;  // the current line went to inih as "key = value"
    bool handled_ = false;   // and inih called the handler for it
    std::string key_text_;
    std::map<std::string, int> first_line_;  // "section.key" -> line
};

}  // namespace

IniFile parse_ini(std::string_view text, std::string name) {
    IniFile file;
    file.name = std::move(name);
    Parser(text, file).run();
    return file;
}

}  // namespace raypoint::config
