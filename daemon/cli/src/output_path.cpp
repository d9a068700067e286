// SPDX-License-Identifier: MIT
#include "raypoint/cli/output_path.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace raypoint::daemon {

void check_output_path(std::string_view option, const std::string& path) {
    const auto fail = [&](const std::string& what, int error) {
        throw std::runtime_error(std::string(option) + " " + path + ": cannot write: " + what +
                                 std::strerror(error) + " (choose another path)");
    };
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0 && S_ISDIR(status.st_mode)) fail("", EISDIR);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    const std::string folder = parent.empty() ? std::string(".") : parent.string();
    if (::stat(folder.c_str(), &status) != 0) fail(folder + ": ", errno);
    if (!S_ISDIR(status.st_mode)) fail(folder + ": ", ENOTDIR);
    if (::access(folder.c_str(), W_OK) != 0) fail(folder + ": ", errno);
}

}  // namespace raypoint::daemon
