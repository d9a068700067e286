#pragma once
// Errors of setup code: complete one-line messages naming the input and the reason.

#include <stdexcept>

namespace raypoint::daemon {

// A bad command line: unknown option, missing value, unknown estimator.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// An input that cannot be read as video: missing, empty, truncated, not a video.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

}  // namespace raypoint::daemon
