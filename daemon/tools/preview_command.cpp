// SPDX-License-Identifier: MIT
#include "preview_command.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "input_error.hpp"
#include "preview_input.hpp"
#include "preview_window.hpp"
#include "raypoint/cli/settings_options.hpp"
#include "raypoint/cli/usage_error.hpp"

namespace raypoint::daemon {

int preview_command(std::span<const std::string_view> args) {
    std::vector<std::string_view> rest;
    const config::Config config = parse_settings_options(args, rest, user_config_file());
    PreviewInputOptions input;
    PreviewLoopOptions loop;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (parse_preview_input_option(rest, i, input)) continue;
        if (!parse_preview_loop_option(rest, i, loop)) {
            throw UsageError(std::string(rest[i]) + ": unknown option (see raypoint --help)");
        }
    }
    loop.ini = ini_to_write(args);
    PreviewInput source(input, config, loop.headless);
    view::PreviewSession session(config);
    const int frames = run_preview_loop(source.frames(), session, loop);
    if (loop.headless) {
        std::printf("raypoint preview: %d frames, last state %s\n", frames,
                    std::string(core::to_string(session.last_result().state)).c_str());
    }
    return 0;
}

}  // namespace raypoint::daemon
