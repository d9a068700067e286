// SPDX-License-Identifier: MIT
#include "raypoint/control/control_socket.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace raypoint::daemon {
namespace {

std::string failure(const std::string& call, const std::string& path) {
    return call + " " + path + ": " + std::strerror(errno);
}

sockaddr_un address_of(const std::string& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path.size() >= sizeof address.sun_path) {
        throw ControlError(path + ": socket path too long (at most " +
                           std::to_string(sizeof address.sun_path - 1) + " bytes)");
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    return address;
}

bool someone_listens(const std::string& path) {
    const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return false;
    const sockaddr_un address = address_of(path);
    const bool answered =
        connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
    close(fd);
    return answered;
}

}  // namespace

std::string_view to_string(ControlCommand command) noexcept {
    switch (command) {
        case ControlCommand::pause:
            return "pause";
        case ControlCommand::resume:
            return "resume";
        case ControlCommand::toggle:
            return "toggle";
        case ControlCommand::recenter:
            return "recenter";
        case ControlCommand::status:
            return "status";
    }
    return "?";
}

std::optional<ControlCommand> control_command_from_string(std::string_view text) noexcept {
    for (const auto command :
         {ControlCommand::pause, ControlCommand::resume, ControlCommand::toggle,
          ControlCommand::recenter, ControlCommand::status}) {
        if (to_string(command) == text) return command;
    }
    return std::nullopt;
}

std::optional<ControlCommand> parse_control_request(std::string_view bytes) noexcept {
    return control_command_from_string(bytes.substr(0, bytes.find('\n')));
}

std::string default_control_path() {
    const char* runtime = std::getenv("XDG_RUNTIME_DIR");
    if (runtime == nullptr || *runtime == '\0') {
        throw ControlError(
            "XDG_RUNTIME_DIR is not set: run raypoint in a user session (systemd --user sets "
            "it), or set it to a private directory");
    }
    return std::string(runtime) + "/raypoint.sock";
}

ControlServer::ControlServer(std::string path) : path_(std::move(path)) {
    const sockaddr_un address = address_of(path_);
    if (someone_listens(path_)) {
        throw ControlError(path_ + ": another raypoint daemon is running (raypoint ctl status)");
    }
    unlink(path_.c_str());  // a socket file a crashed daemon left behind
    listen_fd_ = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    if (listen_fd_ < 0) throw ControlError(failure("socket", path_));
    // bind() creates the file with the umask's mode: 0177 makes it 0600 from the first moment,
    // with no window in which another user could connect. The umask is the process's: nothing
    // else of the daemon creates files while it sets up.
    const mode_t saved_umask = umask(0177);
    const int bound = bind(listen_fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address);
    umask(saved_umask);
    if (bound != 0 || listen(listen_fd_, 4) != 0) {
        const std::string message = failure("bind", path_);
        close(listen_fd_);
        throw ControlError(message);
    }
}

ControlServer::~ControlServer() {
    if (client_fd_ >= 0) close(client_fd_);
    if (listen_fd_ >= 0) {
        close(listen_fd_);
        unlink(path_.c_str());
    }
}

std::optional<ControlCommand> ControlServer::next_request() noexcept {
    if (client_fd_ >= 0) reply("error: no reply was given\n");
    client_fd_ = accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (client_fd_ < 0) return std::nullopt;
    ucred peer{};
    socklen_t peer_size = sizeof peer;
    if (getsockopt(client_fd_, SOL_SOCKET, SO_PEERCRED, &peer, &peer_size) != 0 ||
        peer.uid != geteuid()) {
        // Another user (only root gets past the 0600 file): no answer, not even the state.
        ++refused_peers_;
        close(client_fd_);
        client_fd_ = -1;
        return std::nullopt;
    }
    // One deadline for the whole request, not one a read: a client dribbling a byte at a time
    // holds the loop no longer than one that sends nothing.
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(control_request_timeout_ms);
    char buffer[control_request_limit];
    std::size_t length = 0;
    while (length < sizeof buffer) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd waiting{client_fd_, POLLIN, 0};
        if (poll(&waiting, 1, static_cast<int>(left.count())) <= 0) break;
        const ssize_t got = read(client_fd_, buffer + length, sizeof buffer - length);
        if (got <= 0) break;
        length += static_cast<std::size_t>(got);
        if (std::memchr(buffer, '\n', length) != nullptr) break;
    }
    const std::string_view request(buffer, length);
    if (const auto command = parse_control_request(request)) return command;
    reply("error: unknown command '" + std::string(request.substr(0, request.find('\n'))) +
          "' (allowed: pause|resume|toggle|recenter|status)\n");
    return std::nullopt;
}

void ControlServer::reply(std::string_view text) noexcept {
    if (client_fd_ < 0) return;
    // Best effort: a client that went away loses its answer, the daemon goes on.
    std::size_t sent = 0;
    while (sent < text.size()) {
        const ssize_t n = send(client_fd_, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) break;
        sent += static_cast<std::size_t>(n);
    }
    close(client_fd_);
    client_fd_ = -1;
}

std::string send_control(const std::string& path, ControlCommand command) {
    const sockaddr_un address = address_of(path);
    const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw ControlError(failure("socket", path));
    if (connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        const std::string message =
            failure("connect", path) + " (is the daemon running? systemctl --user status raypoint)";
        close(fd);
        throw ControlError(message);
    }
    const std::string request = std::string(to_string(command)) + "\n";
    if (send(fd, request.data(), request.size(), MSG_NOSIGNAL) !=
        static_cast<ssize_t>(request.size())) {
        const std::string message = failure("send", path);
        close(fd);
        throw ControlError(message);
    }
    std::string reply;
    char buffer[4096];
    for (;;) {
        pollfd waiting{fd, POLLIN, 0};
        if (poll(&waiting, 1, 2000) <= 0) {
            close(fd);
            throw ControlError(path + ": the daemon did not answer within 2 s");
        }
        const ssize_t got = read(fd, buffer, sizeof buffer);
        if (got <= 0) break;
        reply.append(buffer, static_cast<std::size_t>(got));
    }
    close(fd);
    return reply;
}

}  // namespace raypoint::daemon
