// SPDX-License-Identifier: MIT
// SdNotifier against a real AF_UNIX datagram socket set as NOTIFY_SOCKET, as systemd would give
// it: the messages, their payloads and their order are what the service manager sees.

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "raypoint/service/sd_notify.hpp"

namespace {

using raypoint::daemon::SdNotifier;
using namespace std::chrono_literals;

// A bound datagram socket in a fresh temporary directory, exported as NOTIFY_SOCKET.
class NotifySocket {
  public:
    NotifySocket() {
        char dir_template[] = "/tmp/raypoint-notify-XXXXXX";
        if (::mkdtemp(dir_template) == nullptr) throw std::runtime_error("mkdtemp failed");
        dir_ = dir_template;
        path_ = dir_ + "/notify";
        fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        if (fd_ < 0) throw std::runtime_error("socket failed");
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strncpy(address.sun_path, path_.c_str(), sizeof(address.sun_path) - 1);
        if (::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0)
            throw std::runtime_error("bind failed");
        // A test that hangs on a lost message is worse than one that fails.
        timeval timeout{2, 0};
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof(timeout));
        ::setenv("NOTIFY_SOCKET", path_.c_str(), 1);
    }
    ~NotifySocket() {
        ::unsetenv("NOTIFY_SOCKET");
        ::close(fd_);
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    NotifySocket(const NotifySocket&) = delete;
    NotifySocket& operator=(const NotifySocket&) = delete;

    // The next datagram, or "<none>" when nothing arrives within the timeout.
    std::string receive() const {
        char buffer[4096];
        const ssize_t size = ::recvfrom(fd_, buffer, sizeof(buffer), 0, nullptr, nullptr);
        if (size < 0) return "<none>";
        return std::string(buffer, static_cast<std::size_t>(size));
    }
    // True when no datagram is waiting.
    bool empty() const {
        char byte;
        return ::recv(fd_, &byte, 1, MSG_DONTWAIT | MSG_PEEK) < 0;
    }

  private:
    std::string dir_;
    std::string path_;
    int fd_ = -1;
};

void set_watchdog(const char* usec) {
    ::setenv("WATCHDOG_USEC", usec, 1);
    ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
}

void clear_watchdog() {
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
}

TEST(SdNotifier, SendsReadyStatusWatchdogStoppingInOrder) {
    NotifySocket socket;
    set_watchdog("5000000");
    SdNotifier notifier;
    clear_watchdog();
    ASSERT_TRUE(notifier.enabled());
    ASSERT_TRUE(notifier.watchdog_enabled());

    const auto start = SdNotifier::Clock::now();
    notifier.ready();
    notifier.status("tracking, 30.0 fps, CPU 7%");
    ASSERT_TRUE(notifier.watchdog_due(start));
    notifier.pet(start);
    notifier.stopping();

    EXPECT_EQ(socket.receive(), "READY=1");
    EXPECT_EQ(socket.receive(), "STATUS=tracking, 30.0 fps, CPU 7%");
    EXPECT_EQ(socket.receive(), "WATCHDOG=1");
    EXPECT_EQ(socket.receive(), "STOPPING=1");
    EXPECT_TRUE(socket.empty());
}

TEST(SdNotifier, PetsAtHalfTheWatchdogInterval) {
    NotifySocket socket;
    set_watchdog("5000000");  // WatchdogSec=5
    SdNotifier notifier;
    clear_watchdog();
    EXPECT_EQ(notifier.pet_interval(), 2500ms);

    const auto start = SdNotifier::Clock::now();
    notifier.pet(start);
    EXPECT_FALSE(notifier.watchdog_due(start + 2499ms));
    EXPECT_TRUE(notifier.watchdog_due(start + 2500ms));
    notifier.pet(start + 2600ms);
    EXPECT_FALSE(notifier.watchdog_due(start + 5000ms));
    EXPECT_TRUE(notifier.watchdog_due(start + 5100ms));

    EXPECT_EQ(socket.receive(), "WATCHDOG=1");
    EXPECT_EQ(socket.receive(), "WATCHDOG=1");
    EXPECT_TRUE(socket.empty());
}

TEST(SdNotifier, NoWatchdogWithoutWatchdogUsec) {
    NotifySocket socket;
    clear_watchdog();
    SdNotifier notifier;
    EXPECT_TRUE(notifier.enabled());
    EXPECT_FALSE(notifier.watchdog_enabled());
    EXPECT_FALSE(notifier.watchdog_due(SdNotifier::Clock::now()));
    notifier.pet(SdNotifier::Clock::now());
    notifier.ready();
    EXPECT_EQ(socket.receive(), "READY=1");
    EXPECT_TRUE(socket.empty());
}

TEST(SdNotifier, IgnoresAWatchdogMeantForAnotherProcess) {
    NotifySocket socket;
    ::setenv("WATCHDOG_USEC", "5000000", 1);
    ::setenv("WATCHDOG_PID", std::to_string(::getpid() + 1).c_str(), 1);
    SdNotifier notifier;
    clear_watchdog();
    EXPECT_FALSE(notifier.watchdog_enabled());
}

TEST(SdNotifier, StatusWithANewlineStaysOneAssignment) {
    NotifySocket socket;
    SdNotifier notifier;
    notifier.status("lost\nREADY=1");
    EXPECT_EQ(socket.receive(), "STATUS=lost READY=1");
}

TEST(SdNotifier, DoesNothingWithoutNotifySocket) {
    ::unsetenv("NOTIFY_SOCKET");
    set_watchdog("5000000");
    SdNotifier notifier;
    clear_watchdog();
    EXPECT_FALSE(notifier.enabled());
    EXPECT_FALSE(notifier.watchdog_enabled());
    EXPECT_FALSE(notifier.watchdog_due(SdNotifier::Clock::now()));
    // None of these may fail or block without a manager to talk to.
    notifier.ready();
    notifier.status("idle");
    notifier.pet(SdNotifier::Clock::now());
    notifier.stopping();
}

}  // namespace
