// SPDX-License-Identifier: MIT
#pragma once
// Log lines on stderr. Under systemd stderr goes to journald, which reads a leading "<N>" as the
// line's syslog priority (sd-daemon's SD_ERR, SD_WARNING, SD_INFO, SD_DEBUG); on a terminal the
// prefix would only be noise, so it is left off there.
//
//   raypoint::daemon::log::info("camera " + path + " open, " + std::to_string(fps) + " fps");

#include <string_view>

namespace raypoint::daemon::log {

enum class Level { error, warning, info, debug };

// One destination with its prefix decision. The free functions below use one on stderr.
class Logger {
  public:
    // Prefixes unless `fd` is a terminal.
    explicit Logger(int fd) noexcept;
    Logger(int fd, bool prefix) noexcept : fd_(fd), prefix_(prefix) {}

    bool prefixed() const noexcept { return prefix_; }
    Level max_level() const noexcept { return max_level_; }
    // Lines above `level` are dropped (debug is for --verbose: it may come every frame).
    void set_max_level(Level level) noexcept { max_level_ = level; }

    // Writes "<N>message\n" (or "message\n") with one write(2), so lines from several threads
    // do not interleave. A newline inside `message` is written as a space, so that one call
    // stays one journal entry with one priority.
    void write(Level level, std::string_view message) const noexcept;

  private:
    int fd_;
    bool prefix_;
    Level max_level_ = Level::info;
};

// The process's logger on stderr (fd 2), prefixed unless stderr is a terminal.
Logger& stderr_logger() noexcept;

inline void error(std::string_view message) noexcept {
    stderr_logger().write(Level::error, message);
}
inline void warning(std::string_view message) noexcept {
    stderr_logger().write(Level::warning, message);
}
inline void info(std::string_view message) noexcept {
    stderr_logger().write(Level::info, message);
}
inline void debug(std::string_view message) noexcept {
    stderr_logger().write(Level::debug, message);
}

}  // namespace raypoint::daemon::log
