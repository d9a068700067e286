// SPDX-License-Identifier: MIT
#include "raypoint/config/ini_update.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "raypoint/config/ini_file.hpp"

namespace raypoint::config {
namespace {

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r'))
        text.remove_suffix(1);
    return text;
}

// The section a header line names, or nothing when the line is not a header.
std::optional<std::string_view> header(std::string_view line) {
    const std::string_view t = trim(line);
    if (t.size() < 2 || t.front() != '[') return std::nullopt;
    const std::size_t close = t.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    return trim(t.substr(1, close - 1));
}

// Where the value of a "key = value" line begins and ends (before an inline comment, which
// starts at ';' or '#' after whitespace, as the parser reads it).
struct ValueSpan {
    std::string_view key;
    std::size_t begin = 0;
    std::size_t end = 0;
};

std::optional<ValueSpan> key_line(std::string_view line) {
    const std::string_view t = trim(line);
    if (t.empty() || t.front() == ';' || t.front() == '#' || t.front() == '[') return std::nullopt;
    const std::size_t equals = line.find('=');
    if (equals == std::string_view::npos) return std::nullopt;
    ValueSpan span{trim(line.substr(0, equals)), equals + 1, line.size()};
    while (span.begin < line.size() && (line[span.begin] == ' ' || line[span.begin] == '\t'))
        ++span.begin;
    for (std::size_t i = span.begin + 1; i < line.size(); ++i) {
        if ((line[i] == ';' || line[i] == '#') && (line[i - 1] == ' ' || line[i - 1] == '\t')) {
            span.end = i;
            break;
        }
    }
    while (span.end > span.begin &&
           (line[span.end - 1] == ' ' || line[span.end - 1] == '\t' || line[span.end - 1] == '\r'))
        --span.end;
    return span;
}

}  // namespace

std::string update_ini_text(std::string_view text, const Config& config,
                            std::span<const Key* const> keys) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = text.find('\n', start);
        const std::size_t stop = end == std::string_view::npos ? text.size() : end;
        lines.emplace_back(text.substr(start, stop - start));
        start = stop + 1;
    }
    std::vector<bool> done(keys.size(), false);
    std::string_view section;
    for (std::string& line : lines) {
        if (const auto name = header(line)) {
            section = *name;
            continue;
        }
        const auto span = key_line(line);
        if (!span) continue;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            if (keys[k]->section != section || keys[k]->name != span->key) continue;
            // A comment right after the value keeps one space before it.
            std::string changed = line.substr(0, span->begin);
            changed += keys[k]->format(config);
            const std::string_view comment = trim(std::string_view(line).substr(span->end));
            if (!comment.empty()) {
                changed += ' ';
                changed += comment;
            }
            line = std::move(changed);  // `span` pointed into the old text: done with this line
            done[k] = true;
            break;
        }
    }
    // Missing keys: after the last setting of their section, or in a new section at the end.
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (done[k]) continue;
        const std::string entry = std::string(keys[k]->name) + " = " + keys[k]->format(config);
        std::optional<std::size_t> insert_after;
        std::string_view current;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (const auto name = header(lines[i])) {
                current = *name;
                if (current == keys[k]->section) insert_after = i;
            } else if (current == keys[k]->section && key_line(lines[i])) {
                insert_after = i;
            }
        }
        if (insert_after) {
            lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(*insert_after) + 1, entry);
        } else {
            if (!lines.empty() && !trim(lines.back()).empty()) lines.emplace_back();
            lines.push_back(std::string("[").append(keys[k]->section).append("]"));
            lines.push_back(entry);
        }
    }
    std::string out;
    for (const std::string& line : lines)
        out += line + "\n";
    return out;
}

void write_ini_values(const std::filesystem::path& path, const Config& config,
                      std::span<const Key* const> keys) {
    std::string text;
    if (std::filesystem::exists(path)) {
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            throw ConfigError(path.string() + ": cannot open: " + std::strerror(errno) +
                              " (check its permissions)");
        }
        std::ostringstream buffer;
        buffer << in.rdbuf();
        text = buffer.str();
    }
    const std::string updated = update_ini_text(text, config, keys);
    const IniFile parsed = parse_ini(updated, path.string());
    if (!parsed.errors.empty()) throw InvalidConfig(parsed.errors);
    std::error_code ignored;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
    const std::filesystem::path temporary = path.string() + ".new";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw ConfigError("open " + temporary.string() + ": " + std::strerror(errno) +
                              " (check the folder's permissions)");
        }
        out << updated;
        if (!out.flush()) {
            throw ConfigError("write " + temporary.string() + ": " + std::strerror(errno));
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        throw ConfigError("rename " + temporary.string() + " to " + path.string() + ": " +
                          std::strerror(errno));
    }
}

}  // namespace raypoint::config
