// SPDX-License-Identifier: MIT
#pragma once
// Which EventSink the daemon sends its commands to: the uinput device, a file, or nothing.
// The command line spells it `--sink uinput|file:PATH|null` (raypoint/cli/sink_option.hpp).

#include <filesystem>
#include <memory>

#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

namespace raypoint::daemon {

enum class SinkKind { uinput, file, null };

struct SinkSpec {
    SinkKind kind = SinkKind::uinput;
    std::filesystem::path path;  // SinkKind::file only
};

// Creates the sink; throws OutputError (UinputError for the device) when it cannot be set up.
std::unique_ptr<EventSink> make_sink(const SinkSpec& spec, const DeviceProfile& profile);

}  // namespace raypoint::daemon
