// SPDX-License-Identifier: MIT
#pragma once
// Log lines on stderr. Under systemd stderr goes to journald, which reads a leading "<N>" as the
// line's syslog priority (sd-daemon's SD_ERR, SD_WARNING, SD_INFO, SD_DEBUG). The prefix is
// written only when stderr is that journal stream: systemd sets $JOURNAL_STREAM to the stream's
// "device:inode", and a process compares it with its stderr's (systemd.exec(5)), so a terminal,
// a pipe or a file, even one a service redirected, gets plain text.
//
//   raypoint::daemon::log::info("camera " + path + " open, " + std::to_string(fps) + " fps");

#include <string>
#include <string_view>

namespace raypoint::daemon::log {

enum class Level { error, warning, info, debug };

// One destination with its prefix decision. The free functions below use one on stderr.
class Logger {
  public:
    // Prefixes when `fd` is the journal stream $JOURNAL_STREAM names.
    explicit Logger(int fd) noexcept;
    Logger(int fd, bool prefix) noexcept : fd_(fd), prefix_(prefix) {}

    bool prefixed() const noexcept { return prefix_; }
    Level max_level() const noexcept { return max_level_; }
    // Lines above `level` are dropped (debug is for --verbose: it may come every frame).
    void set_max_level(Level level) noexcept { max_level_ = level; }

    // Writes "<N>message\n" (or "message\n") with one write(2), so lines from several threads
    // do not interleave. A newline inside `message` is written as a space, so that one call
    // stays one journal entry with one priority; other control characters as escape_control().
    void write(Level level, std::string_view message) const noexcept;

  private:
    int fd_;
    bool prefix_;
    Level max_level_ = Level::info;
};

// The process's logger on stderr (fd 2), prefixed when stderr is the journal stream.
Logger& stderr_logger() noexcept;

// `text` with every control character but tab written as \xNN (DEL too), so that text from a
// file or the command line (a key named "\x1b]0;title\x07") cannot drive the terminal that
// shows the message. Other bytes, UTF-8 included, pass unchanged.
std::string escape_control(std::string_view text);

// True when `journal_stream` ($JOURNAL_STREAM, "device:inode") names the file `fd` refers to.
bool is_journal_stream(int fd, const char* journal_stream) noexcept;

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
