// SPDX-License-Identifier: MIT
#pragma once
// `raypoint ctl pause|resume|toggle|recenter|status`: a unix stream socket in $XDG_RUNTIME_DIR. One
// request line in, one reply out, then the connection closes. The daemon polls the listening
// socket from its frame loop; nothing here blocks that loop.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raypoint::daemon {

enum class ControlCommand { pause, resume, toggle, recenter, status };

std::string_view to_string(ControlCommand command) noexcept;
std::optional<ControlCommand> control_command_from_string(std::string_view text) noexcept;

// What a client's bytes ask for: the text before the first newline (all of it without one) names
// a command exactly. Nothing else is a request: no spaces, no case folding, no arguments.
std::optional<ControlCommand> parse_control_request(std::string_view bytes) noexcept;

// The most a request may take: bytes read (a command and its newline fit with room) and the
// time from accept to its newline. A client that sends nothing, too much or too slowly gets an
// error reply after at most this long; the frame loop then goes on.
inline constexpr std::size_t control_request_limit = 64;
inline constexpr int control_request_timeout_ms = 50;

// $XDG_RUNTIME_DIR/raypoint.sock. Throws std::runtime_error when XDG_RUNTIME_DIR is unset.
std::string default_control_path();

// A control socket that cannot be set up or reached. The message is complete.
class ControlError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class ControlServer {
  public:
    // Binds and listens at `path`, replacing a stale socket file left by a crashed daemon (but
    // not one a running daemon still answers on). The socket file is mode 0600 from its
    // creation, and only a peer of the daemon's own uid (SO_PEERCRED) is answered: pausing
    // someone's pointer is that user's decision. Throws ControlError.
    explicit ControlServer(std::string path);
    ~ControlServer();
    ControlServer(const ControlServer&) = delete;
    ControlServer& operator=(const ControlServer&) = delete;

    int fd() const noexcept { return listen_fd_; }  // poll for POLLIN
    const std::string& path() const noexcept { return path_; }

    // Accepts one waiting client and reads its request line. Returns nothing when no client is
    // waiting, the client is another user (closed without a word), or the request is not a
    // command (that client gets an error reply at once).
    std::optional<ControlCommand> next_request() noexcept;
    // Answers the client of the last next_request() and closes its connection.
    void reply(std::string_view text) noexcept;

    // Clients refused for their uid, since the start: for `ctl status` and the tests.
    long long refused_peers() const noexcept { return refused_peers_; }

  private:
    std::string path_;
    int listen_fd_ = -1;
    int client_fd_ = -1;
    long long refused_peers_ = 0;
};

// The client side: sends `command` and returns the daemon's reply. Throws ControlError naming
// the socket and what to do when no daemon answers.
std::string send_control(const std::string& path, ControlCommand command);

}  // namespace raypoint::daemon
