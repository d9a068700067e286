// SPDX-License-Identifier: MIT
#pragma once
// `--sink file:PATH`: the evdev events the uinput device would send, one line each, so a test
// compares event streams without a kernel. Same encoder as UinputPointer (pointer_events.hpp).
//
// A line is `t_us EV_TYPE CODE VALUE` with libevdev's names, the SYN_REPORTs included:
//   5033333 EV_REL REL_X -12
//   5033333 EV_SYN SYN_REPORT 0
//   5033333 EV_KEY BTN_LEFT 1
//   5033333 EV_SYN SYN_REPORT 0
// t_us is the frame's timestamp (microseconds) given to emit().

#include <array>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

namespace raypoint::daemon {

class FileSink final : public EventSink {
  public:
    // Creates or truncates `path`; throws OutputError naming it and the reason.
    FileSink(const std::filesystem::path& path, const DeviceProfile& profile);
    // Releases every button down (as the kernel does when a uinput device goes), then closes.
    ~FileSink() override;

    // Writes the command's events and flushes, so a reader sees whole commands.
    void emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept override;
    void release_all(core::Timestamp timestamp) noexcept override;
    std::string_view name() const override { return name_; }
    int last_error() const noexcept override { return last_error_; }

  private:
    void write(const EventBatch& batch, core::Timestamp timestamp) noexcept;

    std::string name_;  // "file:PATH"
    std::FILE* file_ = nullptr;
    // stdio's buffer, given up front so that the first write does not allocate one.
    std::array<char, 4096> buffer_{};
    PointerEncoder encoder_;
    core::Timestamp last_timestamp_ = 0;
    int last_error_ = 0;
};

// One line of the format above, without the newline; empty when `out` is too short. Exposed for
// the tests and for tools that print events the same way.
std::string_view format_event(const EvdevEvent& event, core::Timestamp timestamp,
                              std::span<char> out) noexcept;

}  // namespace raypoint::daemon
