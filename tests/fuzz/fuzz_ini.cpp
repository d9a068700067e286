// SPDX-License-Identifier: MIT
// A configuration file of any bytes through the parser, the schema's values, the preset and the
// cross-checks: every outcome is a Config or messages, never a crash. A file that loads without
// error prints (to_ini) as a file that loads again to the same text: print-config's output is
// always a valid configuration.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_target.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/config/schema.hpp"

namespace {

raypoint::config::Config load(std::string_view text, std::vector<std::string>& errors) {
    using namespace raypoint::config;
    const IniFile file = parse_ini(text, "fuzz.ini");
    errors = file.errors;
    Config config = config_from_file(file, std::nullopt, errors);
    if (errors.empty()) {
        for (const auto& problem : cross_check(config))
            errors.push_back("fuzz.ini: " + problem);  // as load_config() words them
    }
    return config;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> errors;
    const raypoint::config::Config config = load(text, errors);
    // Bounded: at most max_errors messages and the one that says it stopped.
    if (errors.size() > raypoint::config::max_errors + 1) std::abort();
    for (const auto& error : errors) {
        if (error.rfind("fuzz.ini", 0) != 0) {
            std::fprintf(stderr, "a message without the file name: %s\n", error.c_str());
            std::abort();
        }
    }
    if (!errors.empty()) return 0;
    const std::string printed = raypoint::config::to_ini(config);
    std::vector<std::string> again;
    const raypoint::config::Config reread = load(printed, again);
    if (!again.empty() || raypoint::config::to_ini(reread) != printed) {
        std::fprintf(stderr, "print-config's output does not load back:\n%s\n", printed.c_str());
        for (const auto& error : again)
            std::fprintf(stderr, "  %s\n", error.c_str());
        std::abort();
    }
    return 0;
}
