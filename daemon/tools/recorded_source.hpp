// SPDX-License-Identifier: MIT
#pragma once
// The RecordedSourceFactory raypoint-tools gives the command line
// (raypoint/cli/recorded_input.hpp): a file decoded as it plays, or decoded up front and replayed
// as a YUYV camera (--realtime).

#include "raypoint/cli/recorded_input.hpp"

namespace raypoint::daemon {

// Throws InputError (input_error.hpp) when the file cannot be read as video.
std::unique_ptr<FrameSource> make_recorded_source(const RecordedInput& input);

}  // namespace raypoint::daemon
