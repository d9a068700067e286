// SPDX-License-Identifier: MIT
#pragma once
// `raypoint ctl status --json`: the daemon's "key: value" status lines as one JSON object, for
// scripts and desktop widgets.

#include <string>
#include <string_view>

namespace raypoint::daemon {

// Each "key: value" line becomes "key": value, the key with spaces as underscores; a value that
// is a number is a number, several numbers an array, yes/no true/false, anything else a string.
// Lines without ": " are left out. Ends with a newline.
std::string status_json(std::string_view text);

}  // namespace raypoint::daemon
