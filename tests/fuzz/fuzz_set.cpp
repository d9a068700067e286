// SPDX-License-Identifier: MIT
// `--set section.key=value` options of any bytes (one a line), applied in turn to the default
// configuration as the command line does, then the cross-checks: each assignment is taken or
// refused with a ConfigError naming it, never a crash. A configuration the checks accept prints
// as a file that loads without error.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_target.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raypoint::config;
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    Config config;
    apply_preset(config, "default");
    while (!rest.empty()) {
        const auto newline = rest.find('\n');
        const std::string_view assignment = rest.substr(0, newline);
        rest = newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
        try {
            apply_assignment(config, assignment);
        } catch (const ConfigError& e) {
            if (std::string_view(e.what()).rfind("--set ", 0) != 0) {
                std::fprintf(stderr, "a message without --set: %s\n", e.what());
                std::abort();
            }
        }
    }
    if (!cross_check(config).empty()) return 0;
    const std::string printed = to_ini(config);
    const IniFile file = parse_ini(printed, "printed.ini");
    std::vector<std::string> errors = file.errors;
    config_from_file(file, std::nullopt, errors);
    if (!errors.empty()) {
        std::fprintf(stderr, "print-config's output does not load:\n%s\n%s\n", printed.c_str(),
                     errors.front().c_str());
        std::abort();
    }
    return 0;
}
