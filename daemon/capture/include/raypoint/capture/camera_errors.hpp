// SPDX-License-Identifier: MIT
#pragma once
// Camera setup errors: one line naming the device, the failing call, the system's reason and
// what the user can do about it. The per-frame path does not throw (see CaptureStatus).

#include <stdexcept>
#include <string>
#include <vector>

namespace raypoint::daemon {

// Opening or configuring a camera failed. Derived from std::runtime_error like the daemon's
// other setup errors, so main() reports what() and exits.
class CameraError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A process with an open file descriptor on a file.
struct FileHolder {
    int pid = 0;
    std::string name;  // /proc/PID/comm: the executable's name, at most 15 characters
};

// Every process under `proc_root` with a descriptor whose /proc/PID/fd link names `path` (after
// resolving `path`'s own symlinks, so /dev/v4l/by-id/... finds holders of /dev/videoN). Other
// users' descriptors are unreadable unless we are root and are silently left out.
std::vector<FileHolder> find_file_holders(const std::string& path,
                                          const std::string& proc_root = "/proc");

// "<device>: <call>: <strerror(error_number)>" and, for the errors a user can fix, a hint:
// EACCES the 'video' group; EBUSY the other programs holding the device (find_file_holders);
// ENOENT the `capture_devices` that do exist; ENODEV/ENXIO the device being gone.
std::string camera_error_message(const std::string& device, const std::string& call,
                                 int error_number,
                                 const std::vector<std::string>& capture_devices = {});

}  // namespace raypoint::daemon
