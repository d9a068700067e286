// SPDX-License-Identifier: MIT
// raypoint ctl over a real unix socket: the daemon side polled as the frame loop does, the
// client side as `raypoint ctl` runs it.

#include <gtest/gtest.h>

#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <string>
#include <thread>

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

// A connected client socket, or -1.
int connect_to(const std::string& path) {
    const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::snprintf(address.sun_path, sizeof address.sun_path, "%s", path.c_str());
    if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

// Everything the server sends until it closes (or 5 s pass).
std::string read_all(int fd) {
    std::string text;
    char buffer[256];
    pollfd waiting{fd, POLLIN, 0};
    while (poll(&waiting, 1, 5000) == 1) {
        const ssize_t got = read(fd, buffer, sizeof buffer);
        if (got <= 0) break;
        text.append(buffer, static_cast<std::size_t>(got));
    }
    return text;
}

TEST(ControlSocketSecurity, SocketFileIsOnlyTheUsers) {
    const std::string path = temp_socket_path();
    const mode_t saved = umask(0);  // a permissive umask must not make it wider
    ControlServer server(path);
    umask(saved);
    struct stat info {};
    ASSERT_EQ(stat(path.c_str(), &info), 0);
    EXPECT_TRUE(S_ISSOCK(info.st_mode));
    EXPECT_EQ(info.st_mode & 07777, 0600U);
    EXPECT_EQ(info.st_uid, geteuid());
}

// Another user's client (a child that becomes nobody) gets no answer, and the daemon counts it.
// With the file's mode opened up on purpose, the uid check alone stands in the way; with 0600 the
// file itself does. Needs root to change uid: skipped otherwise.
TEST(ControlSocketSecurity, AnotherUsersClientIsRefused) {
    if (geteuid() != 0) GTEST_SKIP() << "needs root to run a client as another uid (nobody)";
    const std::string path = temp_socket_path();
    ControlServer server(path);
    const std::string dir = path.substr(0, path.rfind('/'));
    ASSERT_EQ(chmod(dir.c_str(), 0755), 0);
    ASSERT_EQ(chmod(path.c_str(), 0666), 0);
    constexpr uid_t nobody = 65534;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        if (setgid(nobody) != 0 || setuid(nobody) != 0) _exit(10);
        const int fd = connect_to(path);
        if (fd < 0) _exit(11);
        // The daemon may have closed the connection already: EPIPE, not SIGPIPE, is fine.
        (void)send(fd, "status\n", 7, MSG_NOSIGNAL);
        const std::string reply = read_all(fd);
        _exit(reply.empty() ? 0 : 13);  // closed without a word
    }
    pollfd waiting{server.fd(), POLLIN, 0};
    ASSERT_EQ(poll(&waiting, 1, 5000), 1);
    EXPECT_FALSE(server.next_request().has_value());
    EXPECT_EQ(server.refused_peers(), 1);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "10, 11: the child's set-up failed, 13: it got a reply";

    // With the file at 0600 again, nobody cannot even connect.
    ASSERT_EQ(chmod(path.c_str(), 0600), 0);
    const pid_t second = fork();
    ASSERT_GE(second, 0);
    if (second == 0) {
        if (setgid(nobody) != 0 || setuid(nobody) != 0) _exit(10);
        _exit(connect_to(path) < 0 && errno == EACCES ? 0 : 14);
    }
    ASSERT_EQ(waitpid(second, &status, 0), second);
    EXPECT_EQ(WEXITSTATUS(status), 0) << "14: nobody connected to a 0600 socket";
}

// A client that connects and says nothing, one that dribbles a byte at a time without a newline,
// and one that sends more than a request can be: each gets an error reply within the request
// timeout, so the frame loop waits no longer than that. The bound checked is 20 times the
// timeout: what fails is a wait that grows with the client's patience, not a slow machine.
TEST(ControlSocketSecurity, SilentSlowAndOversizedClientsCannotStallTheLoop) {
    using Clock = std::chrono::steady_clock;
    const auto limit = std::chrono::milliseconds(20 * raypoint::daemon::control_request_timeout_ms);
    const std::string path = temp_socket_path();
    ControlServer server(path);

    const auto served = [&](int client) {
        pollfd waiting{server.fd(), POLLIN, 0};
        EXPECT_EQ(poll(&waiting, 1, 5000), 1);
        const auto start = Clock::now();
        EXPECT_FALSE(server.next_request().has_value());
        const auto took = Clock::now() - start;
        const std::string reply = read_all(client);
        close(client);
        EXPECT_EQ(reply.rfind("error: unknown command", 0), 0U) << reply;
        return took;
    };

    const int silent = connect_to(path);
    ASSERT_GE(silent, 0);
    EXPECT_LT(served(silent), limit);

    const int slow = connect_to(path);
    ASSERT_GE(slow, 0);
    std::atomic<bool> stop{false};
    std::thread dribble([&] {
        // A byte every 20 ms, for up to 3 s: each read comes within a per-read timeout.
        for (int i = 0; i < 150 && !stop; ++i) {
            if (send(slow, "x", 1, MSG_NOSIGNAL) != 1) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    });
    const auto slow_took = served(slow);
    stop = true;
    dribble.join();
    EXPECT_LT(slow_took, limit);

    const int big = connect_to(path);
    ASSERT_GE(big, 0);
    const std::string flood(4096, 'p');
    ASSERT_EQ(send(big, flood.data(), flood.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(flood.size()));
    EXPECT_LT(served(big), limit);
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
