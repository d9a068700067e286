// SPDX-License-Identifier: MIT
#include "status_json.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace raypoint::daemon {
namespace {

bool is_number(const std::string& token) {
    if (token.empty()) return false;
    char* end = nullptr;
    std::strtod(token.c_str(), &end);
    return *end == '\0' && token != "nan" && token != "inf" && token != "-inf";
}

std::string quoted(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char escaped[8];
                    std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                    out += escaped;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

std::string json_value(std::string_view value) {
    if (value == "yes") return "true";
    if (value == "no") return "false";
    std::vector<std::string> tokens;
    for (std::size_t start = 0; start < value.size();) {
        const std::size_t end = std::min(value.find(' ', start), value.size());
        if (end > start) tokens.emplace_back(value.substr(start, end - start));
        start = end + 1;
    }
    for (const auto& token : tokens)
        if (!is_number(token)) return quoted(value);
    if (tokens.size() == 1) return tokens.front();
    if (tokens.empty()) return quoted(value);
    std::string array = "[";
    for (std::size_t i = 0; i < tokens.size(); ++i)
        array += (i ? "," : "") + tokens[i];
    return array + "]";
}

}  // namespace

std::string status_json(std::string_view text) {
    std::string out = "{";
    bool first = true;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        const std::size_t colon = line.find(": ");
        if (colon == std::string_view::npos || colon == 0) continue;
        std::string key(line.substr(0, colon));
        for (char& c : key)
            if (c == ' ') c = '_';
        if (!first) out += ',';
        out.append(quoted(key)).append(":").append(json_value(line.substr(colon + 2)));
        first = false;
    }
    return out + "}\n";
}

}  // namespace raypoint::daemon
