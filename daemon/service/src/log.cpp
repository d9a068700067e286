// SPDX-License-Identifier: MIT
#include "raypoint/service/log.hpp"

#include <sys/stat.h>
#include <systemd/sd-daemon.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
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

bool is_journal_stream(int fd, const char* journal_stream) noexcept {
    if (journal_stream == nullptr) return false;
    // "DEVICE:INODE", both decimal (systemd.exec(5), $JOURNAL_STREAM).
    char* end = nullptr;
    errno = 0;
    const unsigned long long device = std::strtoull(journal_stream, &end, 10);
    if (end == journal_stream || *end != ':' || errno != 0) return false;
    const char* inode_text = end + 1;
    const unsigned long long inode = std::strtoull(inode_text, &end, 10);
    if (end == inode_text || *end != '\0' || errno != 0) return false;
    struct stat status {};
    if (::fstat(fd, &status) != 0) return false;
    return static_cast<unsigned long long>(status.st_dev) == device &&
           static_cast<unsigned long long>(status.st_ino) == inode;
}

Logger::Logger(int fd) noexcept
    : fd_(fd), prefix_(is_journal_stream(fd, std::getenv("JOURNAL_STREAM"))) {}

std::string escape_control(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
            constexpr char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[byte >> 4];
            out += hex[byte & 0xf];
        } else {
            out += c;
        }
    }
    return out;
}

void Logger::write(Level level, std::string_view message) const noexcept {
    if (static_cast<int>(level) > static_cast<int>(max_level_)) return;
    try {
        std::string line;
        line.reserve(message.size() + 5);
        if (prefix_) line += prefix_of(level);
        std::string text(message);
        for (char& c : text)
            if (c == '\n') c = ' ';
        line += escape_control(text);
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
