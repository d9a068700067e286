// SPDX-License-Identifier: MIT
// raypoint-evdev-recorder: what a desktop would read from the daemon's virtual pointer. Waits
// for the /dev/input/eventN named NAME, reads it with libevdev in this separate process and
// prints one line an event until SIGTERM/SIGINT or until the device goes away:
//   device /dev/input/event3 raypoint virtual pointer
//   1234.567890 EV_REL REL_X 12
// Times are CLOCK_MONOTONIC seconds (EVIOCSCLOCKID), the clock the loopback writer reports its
// first frame on, so a transcript line maps to a time in the clip. SYN_REPORTs are left out;
// a SYN_DROPPED (the kernel's buffer overflowed) is printed as "dropped" and exits 1 at the end.
// usage: raypoint-evdev-recorder [--name NAME] [--wait SECONDS]

#include <dirent.h>
#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <thread>

namespace {

struct Options {
    std::string name = "raypoint virtual pointer";
    double wait_seconds = 60;
};

// The first /dev/input/event* whose device name is `name`, opened; -1 if none yet.
int open_named(const std::string& name, std::string& node) {
    DIR* dir = opendir("/dev/input");
    if (!dir) return -1;
    int found = -1;
    while (const dirent* entry = readdir(dir)) {
        if (std::strncmp(entry->d_name, "event", 5) != 0) continue;
        const std::string path = std::string("/dev/input/") + entry->d_name;
        const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) continue;
        char device_name[256] = {};
        if (ioctl(fd, EVIOCGNAME(sizeof device_name - 1), device_name) >= 0 &&
            name == device_name) {
            node = path;
            found = fd;
            break;
        }
        close(fd);
    }
    closedir(dir);
    return found;
}

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--name") {
            options.name = argv[i + 1];
        } else if (flag == "--wait") {
            options.wait_seconds = std::stod(argv[i + 1]);
        } else {
            std::fprintf(stderr, "usage: raypoint-evdev-recorder [--name NAME] [--wait S]\n");
            std::exit(2);
        }
    }
    return options;
}

void print(const input_event& event) {
    std::printf("%lld.%06ld %s %s %d\n", static_cast<long long>(event.input_event_sec),
                static_cast<long>(event.input_event_usec), libevdev_event_type_get_name(event.type),
                libevdev_event_code_get_name(event.type, event.code), event.value);
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse(argc, argv);
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGINT);
    sigprocmask(SIG_BLOCK, &signals, nullptr);
    const int signal_fd = signalfd(-1, &signals, SFD_CLOEXEC | SFD_NONBLOCK);

    std::string node;
    int fd = -1;
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(options.wait_seconds);
    while ((fd = open_named(options.name, node)) < 0) {
        signalfd_siginfo info{};
        if (read(signal_fd, &info, sizeof info) > 0 ||
            std::chrono::steady_clock::now() > deadline) {
            std::printf("no device named \"%s\"\n", options.name.c_str());
            return 1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    libevdev* device = nullptr;
    if (const int error = libevdev_new_from_fd(fd, &device); error < 0) {
        std::printf("libevdev_new_from_fd %s: %s\n", node.c_str(), std::strerror(-error));
        return 1;
    }
    if (const int error = libevdev_set_clock_id(device, CLOCK_MONOTONIC); error < 0) {
        std::printf("libevdev_set_clock_id %s: %s\n", node.c_str(), std::strerror(-error));
        return 1;
    }
    std::printf("device %s %s\n", node.c_str(), libevdev_get_name(device));
    std::fflush(stdout);

    bool dropped = false;
    for (;;) {
        input_event event{};
        const int result = libevdev_next_event(device, LIBEVDEV_READ_FLAG_NORMAL, &event);
        if (result == LIBEVDEV_READ_STATUS_SUCCESS) {
            if (event.type != EV_SYN) print(event);
            continue;
        }
        if (result == LIBEVDEV_READ_STATUS_SYNC) {
            std::printf("dropped\n");
            dropped = true;
            // Drain the sync events; the transcript is incomplete from here on anyway.
            while (libevdev_next_event(device, LIBEVDEV_READ_FLAG_SYNC, &event) ==
                   LIBEVDEV_READ_STATUS_SYNC) {
            }
            continue;
        }
        if (result != -EAGAIN) {
            // ENODEV: the daemon destroyed the device (it exited).
            std::printf("end: %s\n", std::strerror(-result));
            break;
        }
        std::fflush(stdout);
        pollfd waits[2] = {{fd, POLLIN, 0}, {signal_fd, POLLIN, 0}};
        poll(waits, 2, -1);
        if (waits[1].revents & POLLIN) {
            std::printf("end: signal\n");
            break;
        }
    }
    std::fflush(stdout);
    libevdev_free(device);
    close(fd);
    return dropped ? 1 : 0;
}
