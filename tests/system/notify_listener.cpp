// SPDX-License-Identifier: MIT
// raypoint-notify-listener: systemd's side of the notify protocol, for the VM tests. Binds
// SOCKET (a datagram socket, what NOTIFY_SOCKET names), prints every message the daemon sends
// with its CLOCK_MONOTONIC time, until SIGTERM/SIGINT:
//   12.345678 READY=1
// On READY=1 it stops the sender (SIGSTOP, by the pid in its credentials) before anything
// else, lists the devices the sender has open, then lets it go on:
//   12.345679 open at READY=1: /dev/uinput /dev/video0
// so the line shows what was open when READY=1 was sent, not some time later.
// usage: raypoint-notify-listener SOCKET

#include <poll.h>
#include <signal.h>
#include <sys/signalfd.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace {

double monotonic_seconds() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// The /dev nodes among the open descriptors of `pid`, sorted.
std::string open_devices(pid_t pid) {
    std::vector<std::string> nodes;
    std::error_code error;
    const std::filesystem::path fds = "/proc/" + std::to_string(pid) + "/fd";
    for (const auto& entry : std::filesystem::directory_iterator(fds, error)) {
        std::error_code link_error;
        const std::string target = std::filesystem::read_symlink(entry.path(), link_error).string();
        if (!link_error && target.rfind("/dev/", 0) == 0 && target != "/dev/null") {
            nodes.push_back(target);
        }
    }
    if (error) return "(cannot list " + fds.string() + ": " + error.message() + ")";
    std::sort(nodes.begin(), nodes.end());
    std::string text;
    for (const std::string& node : nodes)
        text += " " + node;
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: raypoint-notify-listener SOCKET\n");
        return 2;
    }
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGINT);
    sigprocmask(SIG_BLOCK, &signals, nullptr);
    const int signal_fd = signalfd(-1, &signals, SFD_CLOEXEC);

    const int fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::snprintf(address.sun_path, sizeof address.sun_path, "%s", argv[1]);
    unlink(argv[1]);
    const int on = 1;
    if (fd < 0 || setsockopt(fd, SOL_SOCKET, SO_PASSCRED, &on, sizeof on) < 0 ||
        bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) < 0) {
        std::fprintf(stderr, "raypoint-notify-listener: %s: %s\n", argv[1], std::strerror(errno));
        return 1;
    }
    std::printf("listening on %s\n", argv[1]);
    std::fflush(stdout);
    for (;;) {
        pollfd waits[2] = {{fd, POLLIN, 0}, {signal_fd, POLLIN, 0}};
        if (poll(waits, 2, -1) < 0 && errno != EINTR) break;
        if (waits[1].revents & POLLIN) break;
        if (!(waits[0].revents & POLLIN)) continue;
        char text[4096];
        alignas(cmsghdr) char control[CMSG_SPACE(sizeof(ucred))];
        iovec data{text, sizeof text - 1};
        msghdr message{};
        message.msg_iov = &data;
        message.msg_iovlen = 1;
        message.msg_control = control;
        message.msg_controllen = sizeof control;
        const ssize_t size = recvmsg(fd, &message, 0);
        if (size < 0) continue;
        text[size] = '\0';
        pid_t sender = 0;
        for (cmsghdr* header = CMSG_FIRSTHDR(&message); header;
             header = CMSG_NXTHDR(&message, header)) {
            if (header->cmsg_level == SOL_SOCKET && header->cmsg_type == SCM_CREDENTIALS) {
                ucred credentials{};
                std::memcpy(&credentials, CMSG_DATA(header), sizeof credentials);
                sender = credentials.pid;
            }
        }
        const double at = monotonic_seconds();
        const bool ready = std::strstr(text, "READY=1") != nullptr;
        if (ready && sender > 0) kill(sender, SIGSTOP);
        // One message may hold several assignments, one a line.
        for (char* line = std::strtok(text, "\n"); line; line = std::strtok(nullptr, "\n"))
            std::printf("%.6f %s\n", at, line);
        if (ready && sender > 0) {
            std::printf("%.6f open at READY=1:%s\n", at, open_devices(sender).c_str());
            kill(sender, SIGCONT);
        }
        std::fflush(stdout);
    }
    close(fd);
    unlink(argv[1]);
    return 0;
}
