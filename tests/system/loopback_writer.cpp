// SPDX-License-Identifier: MIT
// raypoint-loopback-writer: a rendered clip as a webcam. `convert` decodes a clip once (on the
// host, where it is fast) into raw YUYV frames, or with --mjpeg into the JPEGs an MJPEG webcam
// sends (4:2:2, quality 85: daemon/tools/jpeg_encoder.hpp); `play` writes them into a
// v4l2loopback node at the clip's pace, as a camera delivers them, so the VM's CPU goes to the
// daemon and not to a video decoder or encoder.
//   raypoint-loopback-writer convert VIDEO OUT.yuyv
//   raypoint-loopback-writer convert VIDEO OUT.mjpg --mjpeg
//   raypoint-loopback-writer play FILE /dev/videoN [--wait] [--from S] [--until S] [--loop]
//                                              [--speed X]
// --speed plays the clip X times as fast (0.25: a 30 fps clip as 7.5 fps, the hand four times
// as slow), for a daemon in an emulator that cannot take frames at the clip's rate. play prints
// "first frame" after its first write (from then on the node is a capture device) and "origin T":
// the CLOCK_MONOTONIC time (s) at which clip time 0 was (would have been) written, so event times
// map to clip times. --wait shows the first frame (an empty scene) at the playing rate until
// SIGUSR1, then plays: the daemon, slow to start in a VM, sees the whole clip after it is ready. It
// writes with write(), one whole frame a call, which v4l2loopback takes as one buffer. SIGTERM or
// --until closes the node: for the daemon that is a camera whose frames stop.

#include <fcntl.h>
#include <linux/videodev2.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "../../daemon/tools/jpeg_encoder.hpp"
#include "../unit/frames.hpp"

namespace {

// The raw file: this header line padded to header_bytes, then `count` frames of width x height
// YUYV (2 bytes a pixel, no row padding). The MJPEG file: its header line ("raypoint-mjpeg",
// the same fields) padded alike, then each frame as its size (4 bytes, the host's order) and
// its JPEG.
constexpr std::size_t header_bytes = 64;
constexpr int mjpeg_quality = 85;

struct Clip {
    int width = 0;
    int height = 0;
    double fps = 0;
    int count = 0;
    int fd = -1;  // frames are read when they are due: no wait for a whole clip to load
    bool mjpeg = false;
    std::vector<off_t> offsets;  // MJPEG: where each frame's JPEG starts
    std::vector<std::uint32_t> sizes;

    std::size_t frame_bytes() const { return std::size_t(width) * std::size_t(height) * 2; }
};

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error(what);
}

[[noreturn]] void fail_errno(const std::string& call) {
    throw std::runtime_error(call + ": " + std::strerror(errno));
}

void convert(const std::string& video_path, const std::string& out_path, bool mjpeg) {
    cv::VideoCapture video(video_path);
    if (!video.isOpened()) fail("cannot open " + video_path);
    const double fps = video.get(cv::CAP_PROP_FPS);
    std::vector<std::uint8_t> frames;
    std::vector<std::uint8_t> jpeg;
    cv::Mat bgr;
    int count = 0;
    int width = 0;
    int height = 0;
    while (video.read(bgr)) {
        if (mjpeg) {
            raypoint::daemon::encode_jpeg(bgr, mjpeg_quality, jpeg);
            const auto size = static_cast<std::uint32_t>(jpeg.size());
            const auto* size_bytes = reinterpret_cast<const std::uint8_t*>(&size);
            frames.insert(frames.end(), size_bytes, size_bytes + sizeof size);
            frames.insert(frames.end(), jpeg.begin(), jpeg.end());
            width = bgr.cols;
            height = bgr.rows;
        } else {
            const raypoint::test::Yuyv yuyv = raypoint::test::to_yuyv(bgr);
            frames.insert(frames.end(), yuyv.bytes.begin(), yuyv.bytes.end());
            width = yuyv.width;
            height = yuyv.height;
        }
        ++count;
    }
    if (count == 0 || width % 2 != 0) fail(video_path + ": no frames, or an odd width");
    char header[header_bytes] = {};
    std::snprintf(header, sizeof header, "%s %d %d %.6f %d\n",
                  mjpeg ? "raypoint-mjpeg" : "raypoint-yuyv", width, height, fps, count);
    std::ofstream out(out_path, std::ios::binary);
    out.write(header, sizeof header);
    out.write(reinterpret_cast<const char*>(frames.data()),
              static_cast<std::streamsize>(frames.size()));
    if (!out.flush()) fail("cannot write " + out_path);
    std::printf("%s: %d %s frames %dx%d at %.3f fps\n", out_path.c_str(), count,
                mjpeg ? "MJPEG" : "YUYV", width, height, fps);
}

Clip load(const std::string& path) {
    Clip clip;
    clip.fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (clip.fd < 0) fail_errno("open " + path);
    char header[header_bytes + 1] = {};
    char kind[16] = {};
    if (pread(clip.fd, header, header_bytes, 0) != static_cast<ssize_t>(header_bytes) ||
        std::sscanf(header, "%15s %d %d %lf %d", kind, &clip.width, &clip.height, &clip.fps,
                    &clip.count) != 5 ||
        clip.fps <= 0 || clip.count <= 0 ||
        (std::strcmp(kind, "raypoint-yuyv") != 0 && std::strcmp(kind, "raypoint-mjpeg") != 0)) {
        fail(path + ": not a raypoint-loopback-writer file");
    }
    clip.mjpeg = std::strcmp(kind, "raypoint-mjpeg") == 0;
    // MJPEG: the frames' places, read once (a few bytes a frame).
    auto at = static_cast<off_t>(header_bytes);
    for (int i = 0; clip.mjpeg && i < clip.count; ++i) {
        std::uint32_t size = 0;
        if (pread(clip.fd, &size, sizeof size, at) != static_cast<ssize_t>(sizeof size))
            fail(path + ": short MJPEG file at frame " + std::to_string(i));
        clip.offsets.push_back(at + static_cast<off_t>(sizeof size));
        clip.sizes.push_back(size);
        at += static_cast<off_t>(sizeof size + size);
    }
    return clip;
}

// Frame `index` of the clip into `frame`.
void read_frame(const Clip& clip, int index, std::vector<std::uint8_t>& frame) {
    const auto at = static_cast<std::size_t>(index);
    frame.resize(clip.mjpeg ? clip.sizes[at] : clip.frame_bytes());
    const auto offset =
        clip.mjpeg ? clip.offsets[at] : static_cast<off_t>(header_bytes + clip.frame_bytes() * at);
    if (pread(clip.fd, frame.data(), frame.size(), offset) != static_cast<ssize_t>(frame.size())) {
        fail("short clip file: frame " + std::to_string(index));
    }
}

double monotonic_seconds() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

void sleep_until(double seconds) {
    timespec at{};
    at.tv_sec = static_cast<time_t>(seconds);
    at.tv_nsec = static_cast<long>((seconds - static_cast<double>(at.tv_sec)) * 1e9);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &at, nullptr) == EINTR) {
    }
}

bool write_frame(int fd, const std::vector<std::uint8_t>& frame) {
    return write(fd, frame.data(), frame.size()) == static_cast<ssize_t>(frame.size());
}

void play(const Clip& clip, const std::string& device, bool wait, double from, double until,
          bool loop, double speed) {
    sigset_t go;
    sigemptyset(&go);
    sigaddset(&go, SIGUSR1);
    sigprocmask(SIG_BLOCK, &go, nullptr);
    const int fd = open(device.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) fail_errno("open " + device);
    v4l2_format format{};
    format.type = V4L2_BUF_TYPE_VIDEO_OUTPUT;
    format.fmt.pix.width = static_cast<__u32>(clip.width);
    format.fmt.pix.height = static_cast<__u32>(clip.height);
    format.fmt.pix.pixelformat = clip.mjpeg ? V4L2_PIX_FMT_MJPEG : V4L2_PIX_FMT_YUYV;
    format.fmt.pix.field = V4L2_FIELD_NONE;
    // A JPEG's buffer: as large as the frame's YUYV (a camera's JPEG is far smaller); each
    // write() of a whole JPEG is one buffer of that many bytes used.
    format.fmt.pix.bytesperline = clip.mjpeg ? 0 : static_cast<__u32>(clip.width * 2);
    format.fmt.pix.sizeimage = static_cast<__u32>(clip.frame_bytes());
    format.fmt.pix.colorspace = clip.mjpeg ? V4L2_COLORSPACE_JPEG : V4L2_COLORSPACE_SMPTE170M;
    if (ioctl(fd, VIDIOC_S_FMT, &format) < 0) {
        fail_errno(std::string("VIDIOC_S_FMT (output, ") + (clip.mjpeg ? "MJPEG" : "YUYV") +
                   ") on " + device);
    }
    const int first = std::max(0, static_cast<int>(std::lround(from * clip.fps)));
    const int last =
        static_cast<int>(std::lround(std::min(until, clip.count / clip.fps) * clip.fps));
    // Clip time t is written at origin + t / speed; a late frame is written at once, never
    // skipped.
    const double rate = clip.fps * speed;  // frames a second written
    std::vector<std::uint8_t> frame;
    read_frame(clip, first, frame);
    if (!write_frame(fd, frame)) fail_errno("write " + device);
    std::printf("first frame\n");
    std::fflush(stdout);
    double next = monotonic_seconds() + 1 / rate;
    const timespec now{};
    while (wait && sigtimedwait(&go, nullptr, &now) != SIGUSR1) {
        sleep_until(next);
        next += 1 / rate;
        if (!write_frame(fd, frame)) fail_errno("write " + device);
    }
    const double origin = next - first / rate;
    std::printf("origin %.6f\n", origin);
    std::fflush(stdout);
    double loop_start = origin;
    do {
        for (int i = first; i < last; ++i) {
            read_frame(clip, i, frame);
            sleep_until(loop_start + i / rate);
            if (!write_frame(fd, frame)) fail_errno("write " + device);
        }
        loop_start += (last - first) / rate;
    } while (loop);
    close(fd);
    std::printf("closed at %.6f\n", monotonic_seconds());
}

}  // namespace

int main(int argc, char** argv) {
    const std::string usage =
        "usage: raypoint-loopback-writer convert VIDEO OUT.yuyv\n"
        "       raypoint-loopback-writer convert VIDEO OUT.mjpg --mjpeg\n"
        "       raypoint-loopback-writer play FILE /dev/videoN [--wait] [--from S] "
        "[--until S] [--loop] [--speed X]\n";
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if ((args.size() == 3 || (args.size() == 4 && args[3] == "--mjpeg")) &&
            args[0] == "convert") {
            convert(args[1], args[2], args.size() == 4);
            return 0;
        }
        if (args.size() < 3 || args[0] != "play") {
            std::fputs(usage.c_str(), stderr);
            return 2;
        }
        bool wait = false;
        double from = 0;
        double until = 1e9;
        bool loop = false;
        double speed = 1;
        for (std::size_t i = 3; i < args.size(); ++i) {
            if (args[i] == "--loop") {
                loop = true;
            } else if (args[i] == "--wait") {
                wait = true;
            } else if (args[i] == "--from" && i + 1 < args.size()) {
                from = std::stod(args[++i]);
            } else if (args[i] == "--until" && i + 1 < args.size()) {
                until = std::stod(args[++i]);
            } else if (args[i] == "--speed" && i + 1 < args.size() && std::stod(args[i + 1]) > 0) {
                speed = std::stod(args[++i]);
            } else {
                std::fputs(usage.c_str(), stderr);
                return 2;
            }
        }
        play(load(args[1]), args[2], wait, from, until, loop, speed);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raypoint-loopback-writer: %s\n", error.what());
        return 1;
    }
    return 0;
}
