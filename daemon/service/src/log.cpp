// SPDX-License-Identifier: MIT
#include "raypoint/service/log.hpp"

#include <systemd/sd-daemon.h>
#include <unistd.h>

#include <cerrno>
#include <string>

namespace raypoint::daemon::log {

namespace {

// SD_ERR and friends are string literals ("<3>"); their text is what journald parses.
std::string_view prefix_of(Level level) noexcept {
    switch (level) {
        case Level::error:
            return SD_ERR;
        case Level::warning:
            return SD_WARNING;
        case Level::info:
            return SD_INFO;
        case Level::debug:
            return SD_DEBUG;
    }
    return SD_ERR;
}

void write_all(int fd, const char* data, std::size_t size) noexcept {
    while (size > 0) {
        const ssize_t written = ::write(fd, data, size);
        if (written < 0) {
            if (errno == EINTR) continue;
            return;  // Nowhere left to report a failing log.
        }
        data += written;
        size -= static_cast<std::size_t>(written);
    }
}

}  // namespace

Logger::Logger(int fd) noexcept : fd_(fd), prefix_(::isatty(fd) == 0) {}

void Logger::write(Level level, std::string_view message) const noexcept {
    if (static_cast<int>(level) > static_cast<int>(max_level_)) return;
    try {
        std::string line;
        line.reserve(message.size() + 5);
        if (prefix_) line += prefix_of(level);
        line += message;
        for (std::size_t i = line.size() - message.size(); i < line.size(); ++i)
            if (line[i] == '\n') line[i] = ' ';
        line += '\n';
        write_all(fd_, line.data(), line.size());
    } catch (...) {
        // No memory for the line: writing the pieces unbuffered is still better than nothing.
        if (prefix_) write_all(fd_, prefix_of(level).data(), prefix_of(level).size());
        write_all(fd_, message.data(), message.size());
        write_all(fd_, "\n", 1);
    }
}

Logger& stderr_logger() noexcept {
    static Logger logger(STDERR_FILENO);
    return logger;
}

}  // namespace raypoint::daemon::log
