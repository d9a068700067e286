// SPDX-License-Identifier: MIT
#pragma once
// A bad command line: unknown option, missing value, unknown estimator or preset. cli_main
// (cli.hpp) prints its message after the command's name and exits 2, the usage exit code.

#include <stdexcept>

namespace raypoint::daemon {

class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace raypoint::daemon
