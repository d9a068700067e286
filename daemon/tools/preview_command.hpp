// SPDX-License-Identifier: MIT
#pragma once
// `raypoint preview [--camera DEV | --input CLIP]`: the camera picture with the tracker's view
// drawn on it, live, with trackbars for the most-tuned settings (preview_window.hpp).

#include <span>
#include <string_view>

namespace raypoint::daemon {

int preview_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
