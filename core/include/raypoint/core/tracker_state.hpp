#pragma once
// The five states of the paper's tracking system (section 4.2); docs/state-machine.md draws them.

#include <string_view>

namespace raypoint::core {

enum class TrackerState {
    initializing,  // waiting startup_seconds of frame time for the camera's exposure to settle
    searching,     // waiting for enough movement to pick a target
    tracking,      // estimating the target's projection features each frame
    validating,    // checking the new inner point's colour against the previous frame's
    recovering,    // trying recovery points around a failed inner point
};

// Lower case, as printed in the JSONL output.
std::string_view to_string(TrackerState state) noexcept;

}  // namespace raypoint::core
