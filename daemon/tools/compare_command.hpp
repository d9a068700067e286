// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace raypoint::daemon {

// `raypoint compare-estimators [--out FILE]`: the paper's comparison of the four estimators
// (section 3), measured on rendered convex and non-convex targets with the inner point started
// in a wide area and in an isolated one; writes the Markdown of docs/estimators.md.
int compare_command(std::span<const std::string_view> args);

}  // namespace raypoint::daemon
