#pragma once
// `--sink uinput|file:PATH|null`: which EventSink the daemon sends its commands to.

#include <filesystem>
#include <memory>
#include <string_view>

#include "event_sink.hpp"
#include "pointer_events.hpp"

namespace raypoint::daemon {

enum class SinkKind { uinput, file, null };

struct SinkSpec {
    SinkKind kind = SinkKind::uinput;
    std::filesystem::path path;  // SinkKind::file only
};

// The value of --sink; throws UsageError naming the value and the allowed forms.
SinkSpec parse_sink_spec(std::string_view value);

// Creates the sink; throws OutputError (UinputError for the device) when it cannot be set up.
std::unique_ptr<EventSink> make_sink(const SinkSpec& spec, const DeviceProfile& profile);

}  // namespace raypoint::daemon
