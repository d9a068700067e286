// SPDX-License-Identifier: MIT
#pragma once
// An input that cannot be read as video or truth: missing, empty, truncated, not a video, a
// malformed truth.jsonl or masks.npz. The message names the path and the reason in one line;
// cli_main (raypoint/cli/cli.hpp) prints it and exits 1.

#include <stdexcept>

namespace raypoint::daemon {

class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace raypoint::daemon
