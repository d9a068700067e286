// SPDX-License-Identifier: MIT
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

// Why TRACKING gave a target up (paper 4.2 lists the first four).
enum class LossReason {
    none,
    too_small,          // area under min_area
    too_large,          // area over max_area: usually rays leaking through a broken outline
    still,              // no movement for idle_seconds
    left,               // kept while still, but its colour no longer matches: it has gone
    no_recovery_point,  // no recovery point matches the previous inner point's colour
    recovery_failed,    // the re-estimated inner point did not validate
    elsewhere,          // the target holds still while the scene's motion is somewhere else
};

// Lower case, as printed in the JSONL output.
std::string_view to_string(TrackerState state) noexcept;
std::string_view to_string(LossReason reason) noexcept;

}  // namespace raypoint::core
