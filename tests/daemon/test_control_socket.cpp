// SPDX-License-Identifier: MIT
// raypoint ctl over a real unix socket: the daemon side polled as the frame loop does, the
// client side as `raypoint ctl` runs it.

#include <gtest/gtest.h>

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <string>

#include "raypoint/control/control_socket.hpp"

namespace {

using raypoint::daemon::ControlCommand;
using raypoint::daemon::ControlError;
using raypoint::daemon::ControlServer;
using raypoint::daemon::send_control;

std::string temp_socket_path() {
    char pattern[] = "/tmp/raypoint-ctl-XXXXXX";
    const char* dir = mkdtemp(pattern);
    return std::string(dir) + "/raypoint.sock";
}

// Serves requests until `count` were answered, replying "<command> ok".
void serve(ControlServer& server, int count) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (count > 0 && std::chrono::steady_clock::now() < deadline) {
        pollfd waiting{server.fd(), POLLIN, 0};
        if (poll(&waiting, 1, 100) <= 0) continue;
        if (const auto command = server.next_request()) {
            server.reply(std::string(raypoint::daemon::to_string(*command)) + " ok\n");
            --count;
        }
    }
}

TEST(ControlSocket, EveryCommandGetsItsReply) {
    const std::string path = temp_socket_path();
    ControlServer server(path);
    auto replies = std::async(std::launch::async, [&] {
        std::string all;
        for (const auto command : {ControlCommand::pause, ControlCommand::resume,
                                   ControlCommand::recenter, ControlCommand::status}) {
            all += send_control(path, command);
        }
        return all;
    });
    serve(server, 4);
    EXPECT_EQ(replies.get(), "pause ok\nresume ok\nrecenter ok\nstatus ok\n");
}

TEST(ControlSocket, UnknownRequestIsAnsweredWithTheAllowedCommands) {
    const std::string path = temp_socket_path();
    ControlServer server(path);
    auto reply = std::async(std::launch::async, [&] {
        const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::snprintf(address.sun_path, sizeof address.sun_path, "%s", path.c_str());
        EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
        EXPECT_EQ(write(fd, "jump\n", 5), 5);
        char buffer[256] = {};
        const ssize_t got = read(fd, buffer, sizeof buffer - 1);
        close(fd);
        return std::string(buffer, got > 0 ? static_cast<std::size_t>(got) : 0);
    });
    pollfd waiting{server.fd(), POLLIN, 0};
    ASSERT_EQ(poll(&waiting, 1, 5000), 1);
    EXPECT_FALSE(server.next_request().has_value());
    EXPECT_EQ(reply.get(),
              "error: unknown command 'jump' (allowed: pause|resume|toggle|recenter|status)\n");
}

TEST(ControlSocket, NoDaemonMeansAClearError) {
    const std::string path = temp_socket_path();
    try {
        send_control(path, ControlCommand::status);
        FAIL() << "expected ControlError";
    } catch (const ControlError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("connect " + path), std::string::npos) << message;
        EXPECT_NE(message.find("is the daemon running?"), std::string::npos) << message;
    }
}

TEST(ControlSocket, SecondDaemonIsRefusedAndStaleSocketReplaced) {
    const std::string path = temp_socket_path();
    {
        ControlServer first(path);
        EXPECT_THROW(ControlServer second(path), ControlError);
    }
    // A crashed daemon leaves its socket file: a new one takes it over.
    const int stale = socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::snprintf(address.sun_path, sizeof address.sun_path, "%s", path.c_str());
    ASSERT_EQ(bind(stale, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    close(stale);
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_NO_THROW(ControlServer replacement(path));
    EXPECT_FALSE(std::filesystem::exists(path)) << "the socket file is removed on exit";
}

TEST(ControlSocket, DefaultPathNeedsXdgRuntimeDir) {
    const char* saved = std::getenv("XDG_RUNTIME_DIR");
    const std::string restore = saved != nullptr ? saved : "";
    unsetenv("XDG_RUNTIME_DIR");
    EXPECT_THROW(raypoint::daemon::default_control_path(), ControlError);
    setenv("XDG_RUNTIME_DIR", "/run/user/1000", 1);
    EXPECT_EQ(raypoint::daemon::default_control_path(), "/run/user/1000/raypoint.sock");
    if (saved != nullptr) {
        setenv("XDG_RUNTIME_DIR", restore.c_str(), 1);
    } else {
        unsetenv("XDG_RUNTIME_DIR");
    }
}

}  // namespace
