// SPDX-License-Identifier: MIT
#include "raypoint/capture/camera_errors.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>

namespace raypoint::daemon {

namespace fs = std::filesystem;

namespace {

std::optional<int> as_pid(const std::string& name) {
    int pid = 0;
    const char* end = name.data() + name.size();
    const auto [ptr, error] = std::from_chars(name.data(), end, pid);
    if (error != std::errc() || ptr != end || pid <= 0) return std::nullopt;
    return pid;
}

std::string process_name(const fs::path& process_dir) {
    std::ifstream comm(process_dir / "comm");
    std::string name;
    std::getline(comm, name);
    return name.empty() ? "?" : name;
}

bool holds(const fs::path& process_dir, const fs::path& target) {
    std::error_code error;
    // Unreadable (another user's process) or gone (exited during the scan): not a holder we
    // can name; the iterator's error_code overload keeps either from throwing.
    for (fs::directory_iterator fd(process_dir / "fd", error), end; !error && fd != end;
         fd.increment(error)) {
        std::error_code link_error;
        if (fs::read_symlink(fd->path(), link_error) == target && !link_error) return true;
    }
    return false;
}

std::string holders_hint(const std::string& device) {
    // V4L2 allows many opens; the conflict comes at VIDIOC_S_FMT or REQBUFS, when we hold the
    // device ourselves. Naming ourselves would send the user looking in the wrong place.
    auto holders = find_file_holders(device);
    std::erase_if(holders, [](const FileHolder& holder) { return holder.pid == getpid(); });
    if (holders.empty()) {
        return "; another program holds the camera (close it; `fuser -v " + device +
               "` may name it if it runs as another user)";
    }
    std::string text = "; another program holds the camera:";
    for (const auto& holder : holders) {
        text += " " + holder.name + " (pid " + std::to_string(holder.pid) + ")";
    }
    return text + "; close it and retry";
}

std::string devices_hint(const std::vector<std::string>& capture_devices) {
    if (capture_devices.empty()) {
        return "; there is no video capture device (is the camera plugged in? `ls /dev/video*`)";
    }
    std::string text = "; the capture devices are:";
    for (const auto& device : capture_devices)
        text += " " + device + ",";
    text.back() = ' ';
    return text + "(or use 'auto')";
}

}  // namespace

std::vector<FileHolder> find_file_holders(const std::string& path, const std::string& proc_root) {
    std::error_code error;
    fs::path target = fs::canonical(path, error);
    if (error) target = fs::absolute(path, error);
    std::vector<FileHolder> holders;
    for (fs::directory_iterator it(proc_root, error), end; !error && it != end;
         it.increment(error)) {
        const auto pid = as_pid(it->path().filename().string());
        if (!pid || !holds(it->path(), target)) continue;
        holders.push_back({*pid, process_name(it->path())});
    }
    return holders;
}

std::string camera_error_message(const std::string& device, const std::string& call,
                                 int error_number,
                                 const std::vector<std::string>& capture_devices) {
    std::string message = device + ": " + call + ": " + std::strerror(error_number);
    switch (error_number) {
        case EACCES:
        case EPERM:
            return message +
                   "; add your user to the 'video' group (sudo usermod -aG video $USER, then "
                   "log in again)";
        case EBUSY:
            return message + holders_hint(device);
        case ENOENT:
            return message + devices_hint(capture_devices);
        case ENODEV:
        case ENXIO:
            return message + "; the camera is gone (unplugged?)";
        default:
            return message;
    }
}

}  // namespace raypoint::daemon
