// SPDX-License-Identifier: MIT
#include "raypoint/output/file_sink.hpp"

#include <libevdev/libevdev.h>

#include <cerrno>
#include <charconv>
#include <cstring>

namespace raypoint::daemon {

namespace {

// Appends `text` at `at`; false when it does not fit.
bool append(std::span<char> out, std::size_t& at, std::string_view text) noexcept {
    if (text.size() > out.size() - at) return false;
    std::memcpy(out.data() + at, text.data(), text.size());
    at += text.size();
    return true;
}

template <typename Integer>
bool append_number(std::span<char> out, std::size_t& at, Integer value) noexcept {
    const auto [end, error] = std::to_chars(out.data() + at, out.data() + out.size(), value);
    if (error != std::errc{}) return false;
    at = static_cast<std::size_t>(end - out.data());
    return true;
}

// libevdev's name, or the number for a type or code it does not know (none we emit).
bool append_name(std::span<char> out, std::size_t& at, const char* name, unsigned int number) {
    return name != nullptr ? append(out, at, name) : append_number(out, at, number);
}

}  // namespace

std::string_view format_event(const EvdevEvent& event, core::Timestamp timestamp,
                              std::span<char> out) noexcept {
    std::size_t at = 0;
    const bool fits =
        append_number(out, at, timestamp) && append(out, at, " ") &&
        append_name(out, at, libevdev_event_type_get_name(event.type), event.type) &&
        append(out, at, " ") &&
        append_name(out, at, libevdev_event_code_get_name(event.type, event.code), event.code) &&
        append(out, at, " ") && append_number(out, at, event.value);
    return fits ? std::string_view(out.data(), at) : std::string_view();
}

FileSink::FileSink(const std::filesystem::path& path, const DeviceProfile& profile)
    : name_("file:" + path.string()), encoder_(profile) {
    // "e": O_CLOEXEC, so programs the daemon may start do not inherit the file.
    file_ = std::fopen(path.c_str(), "we");
    if (file_ == nullptr) {
        throw OutputError("--sink " + name_ + ": cannot write " + path.string() + ": " +
                          std::strerror(errno));
    }
    std::setvbuf(file_, buffer_.data(), _IOFBF, buffer_.size());
}

FileSink::~FileSink() {
    release_all(last_timestamp_);
    std::fclose(file_);
}

void FileSink::emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept {
    write(encoder_.encode(command), timestamp);
}

void FileSink::release_all(core::Timestamp timestamp) noexcept {
    write(encoder_.release_all(), timestamp);
}

void FileSink::write(const EventBatch& batch, core::Timestamp timestamp) noexcept {
    last_timestamp_ = timestamp;
    if (batch.empty()) return;
    for (const EvdevEvent& event : batch.events()) {
        // The longest line is about 60 characters; one is kept back for the newline.
        std::array<char, 96> line_buffer{};
        std::string_view line = format_event(
            event, timestamp, std::span<char>(line_buffer.data(), line_buffer.size() - 1));
        line_buffer[line.size()] = '\n';
        line = std::string_view(line_buffer.data(), line.size() + 1);
        if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) {
            last_error_ = errno != 0 ? errno : EIO;
        }
    }
    if (std::fflush(file_) != 0) last_error_ = errno != 0 ? errno : EIO;
}

}  // namespace raypoint::daemon
