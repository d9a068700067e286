// SPDX-License-Identifier: MIT
#pragma once
// The systemd notify protocol for `raypoint run` as a Type=notify user service: READY=1 once the
// camera and uinput are open, STATUS= lines for `systemctl --user status`, WATCHDOG=1 from the
// frame loop and STOPPING=1. Outside systemd (no NOTIFY_SOCKET) every call does nothing, so the
// daemon calls these unconditionally.

#include <chrono>
#include <string_view>

namespace raypoint::daemon {

class SdNotifier {
  public:
    using Clock = std::chrono::steady_clock;

    // Reads NOTIFY_SOCKET, WATCHDOG_USEC and WATCHDOG_PID now. They stay in the environment
    // (sd_notify's unset_environment is 0): every later message needs NOTIFY_SOCKET, and the
    // daemon starts no child that could inherit them by mistake.
    SdNotifier();

    bool enabled() const noexcept { return enabled_; }
    bool watchdog_enabled() const noexcept { return watchdog_interval_.count() > 0; }
    // How often pet() is due: half the unit's WatchdogSec=, zero when the watchdog is off.
    std::chrono::microseconds pet_interval() const noexcept { return watchdog_interval_ / 2; }

    void ready() noexcept;
    // One line for `systemctl --user status`, e.g. "tracking, 30.0 fps, CPU 7%".
    void status(std::string_view text) noexcept;
    void stopping() noexcept;

    // True when the watchdog is on and half its interval has passed since the last pet().
    bool watchdog_due(Clock::time_point now) const noexcept;
    // Sends WATCHDOG=1 and restarts the half-interval.
    void pet(Clock::time_point now) noexcept;

  private:
    void send(const char* message) noexcept;

    bool enabled_ = false;
    std::chrono::microseconds watchdog_interval_{0};
    // The first watchdog_due() is true at once, so a pet goes out with the first frame.
    Clock::time_point last_pet_{};
};

}  // namespace raypoint::daemon
