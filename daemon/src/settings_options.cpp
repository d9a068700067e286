#include "settings_options.hpp"

#include <string>

#include "errors.hpp"
#include "raypoint/config/schema.hpp"

namespace raypoint::daemon {

std::string_view option_value(std::span<const std::string_view> args, std::size_t& i) {
    if (i + 1 >= args.size()) throw UsageError(std::string(args[i]) + ": missing value");
    return args[++i];
}

config::Config parse_settings_options(std::span<const std::string_view> args,
                                      std::vector<std::string_view>& rest) {
    config::Config config;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] != "--preset") continue;
        const std::string_view name = option_value(args, i);
        if (!config::apply_preset(config, name)) {
            throw UsageError("--preset " + std::string(name) +
                             ": unknown preset (allowed: default|paper)");
        }
    }
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view option = args[i];
        if (option == "--preset") {
            ++i;
        } else if (option == "--set") {
            config::apply_assignment(config, option_value(args, i));
        } else if (option == "--estimator") {
            const std::string_view name = option_value(args, i);
            const config::Key* key = config::find_key("estimator", "method");
            if (key->parse(config, name)) {
                throw UsageError("--estimator " + std::string(name) +
                                 ": unknown estimator (allowed: " + key->allowed() + ")");
            }
        } else {
            rest.push_back(option);
        }
    }
    const auto problems = config::cross_check(config);
    if (!problems.empty()) throw config::ConfigError(problems.front());
    return config;
}

}  // namespace raypoint::daemon
