// SPDX-License-Identifier: MIT
#pragma once
// Where the daemon sends each frame's PointerCommand: the uinput device, a file of the events the
// device would send (tests compare streams), or nowhere (benchmarks). sink_factory.hpp picks one.

#include <stdexcept>
#include <string_view>

#include "raypoint/core/frame.hpp"
#include "raypoint/core/pointer_command.hpp"

namespace raypoint::daemon {

// A sink that cannot be set up: a complete one-line message naming the call or file, the reason,
// and what to do about it.
class OutputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class EventSink {
  public:
    EventSink() = default;
    EventSink(const EventSink&) = delete;
    EventSink& operator=(const EventSink&) = delete;
    virtual ~EventSink() = default;

    // One frame's command. Runs every frame: never throws, never allocates. A failed write is
    // kept in last_error() rather than thrown, so one lost event cannot stop the daemon.
    virtual void emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept = 0;
    // Releases every button the sink has pressed: for exit, signals, pause and tracking loss,
    // so that no button stays down when the daemon stops driving it.
    virtual void release_all(core::Timestamp timestamp) noexcept = 0;
    virtual std::string_view name() const = 0;
    // The errno of the most recent failed write, 0 when every write so far succeeded.
    virtual int last_error() const noexcept { return 0; }
    // Batches (one a command or release_all) with a failed write, since the start.
    virtual long long failed_writes() const noexcept { return 0; }
};

// Drops everything: the daemon's own cost without an output (benchmarks).
class NullSink final : public EventSink {
  public:
    void emit(const core::PointerCommand& command, core::Timestamp timestamp) noexcept override;
    void release_all(core::Timestamp timestamp) noexcept override;
    std::string_view name() const override { return "null"; }
};

}  // namespace raypoint::daemon
