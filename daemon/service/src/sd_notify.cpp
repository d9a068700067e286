// SPDX-License-Identifier: MIT
#include "raypoint/service/sd_notify.hpp"

#include <systemd/sd-daemon.h>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace raypoint::daemon {

SdNotifier::SdNotifier() {
    const char* socket = std::getenv("NOTIFY_SOCKET");
    enabled_ = socket != nullptr && socket[0] != '\0';
    if (!enabled_) return;
    // sd_watchdog_enabled also checks WATCHDOG_PID against our pid, so a watchdog meant for a
    // parent (a wrapper script) is not petted from here.
    std::uint64_t usec = 0;
    if (sd_watchdog_enabled(0, &usec) > 0) watchdog_interval_ = std::chrono::microseconds(usec);
}

void SdNotifier::ready() noexcept {
    send("READY=1");
}

void SdNotifier::stopping() noexcept {
    send("STOPPING=1");
}

void SdNotifier::status(std::string_view text) noexcept {
    if (!enabled_) return;
    try {
        std::string message = "STATUS=";
        message += text;
        // The protocol is newline-separated assignments: a newline in the text would end STATUS=
        // early and make the rest a (bogus) assignment of its own.
        for (std::size_t i = 7; i < message.size(); ++i)
            if (message[i] == '\n') message[i] = ' ';
        send(message.c_str());
    } catch (...) {
        // Out of memory for a status line: skip the line rather than stop the frame loop.
    }
}

bool SdNotifier::watchdog_due(Clock::time_point now) const noexcept {
    return watchdog_enabled() && now - last_pet_ >= pet_interval();
}

void SdNotifier::pet(Clock::time_point now) noexcept {
    if (!watchdog_enabled()) return;
    last_pet_ = now;
    send("WATCHDOG=1");
}

void SdNotifier::send(const char* message) noexcept {
    if (!enabled_) return;
    // A failed notification is not worth stopping the pointer for: systemd's own timeouts and
    // the watchdog report a daemon whose messages do not arrive.
    (void)sd_notify(0, message);
}

}  // namespace raypoint::daemon
