// SPDX-License-Identifier: MIT
#pragma once
// `--sink uinput|file:PATH|null`: the command line's spelling of a SinkSpec.

#include <string_view>

#include "raypoint/output/sink_factory.hpp"

namespace raypoint::daemon {

// The value of --sink; throws UsageError naming the value and the allowed forms.
SinkSpec parse_sink_spec(std::string_view value);

}  // namespace raypoint::daemon
