// SPDX-License-Identifier: MIT
#pragma once
// `raypoint eval-clicks [--set-name full|ci|none] [--seed N] [--backgrounds DIR] [--jobs N]
// [--sweep] [--plot PNG] [--write DIR] [CLIP...]`: the pointer on the click gesture set (and on
// recorded clips, each with its truth in CLIP.clicks): recall, precision, false clicks per
// minute, latency and offset, per condition (docs/clicks.md).

#include <span>
#include <string_view>

namespace raypoint::daemon {

int eval_clicks_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
