// SPDX-License-Identifier: MIT
#include "doctor_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "raypoint/capture/v4l2_device.hpp"
#include "raypoint/cli/usage_error.hpp"
#include "raypoint/config/config_paths.hpp"
#include "raypoint/config/ini_file.hpp"
#include "raypoint/control/control_socket.hpp"
#include "raypoint/core/instruction_trial.hpp"
#include "raypoint/core/tracker.hpp"
#include "raypoint/loop/instruction_report.hpp"
#include "raypoint/loop/yuyv_clip.hpp"

namespace raypoint::daemon {
namespace {

struct Check {
    bool ok = true;
    std::string what;  // one line: what was found
    std::string fix;   // when not ok: what to do about it
};

void print(const std::string& area, const Check& check, int& failures) {
    std::printf("%-4s %-8s %s\n", check.ok ? "ok" : "FAIL", area.c_str(), check.what.c_str());
    if (!check.ok) {
        std::printf("     fix: %s\n", check.fix.c_str());
        ++failures;
    }
}

// A warning, not a failure: what root can do a user can too, so root changes no other check's
// outcome, but a service run as root would hide the missing group or udev rule a user meets.
void print_root_note() {
    if (geteuid() != 0) {
        std::printf(
            "%-4s %-8s %s\n", "ok", "user",
            ("runs as uid " + std::to_string(geteuid()) + ", not root (raypoint never needs root)")
                .c_str());
        return;
    }
    std::printf("%-4s %-8s %s\n", "note", "user",
                "running as root: raypoint never needs root, and the checks below are root's");
    std::printf(
        "     fix: run raypoint as the user whose pointer it drives (systemctl --user "
        "start raypoint); the camera needs the video group, /dev/uinput the udev rule\n");
}

// The device node can be opened for reading and writing by this user.
std::string access_problem(const std::string& path) {
    if (access(path.c_str(), R_OK | W_OK) == 0) return {};
    return std::strerror(errno);
}

Check check_config(config::Config& loaded) {
    const auto path = config::find_config_file();
    if (!path) return {true, "no configuration file: the defaults (raypoint print-config)", ""};
    try {
        loaded = config::load_config(*path);
        return {true, path->string() + " is valid", ""};
    } catch (const config::InvalidConfig& e) {
        std::string what = path->string() + " has " + std::to_string(e.errors().size()) +
                           " error(s), the first: " + e.errors().front();
        return {false, what, "raypoint check-config lists them all; edit the file"};
    } catch (const std::exception& e) {
        return {false, e.what(), "fix the file's permissions, or remove it to use the defaults"};
    }
}

Check check_camera(const config::Config& settings) {
    const std::vector<std::string> cameras = list_capture_devices();
    if (cameras.empty()) {
        return {false, "no webcam (no video capture device under /dev)",
                "plug a webcam in; `ls /dev/video*` should list it (a VM needs a passed-through "
                "or virtual camera, e.g. modprobe vivid)"};
    }
    const std::string& device = settings.camera.device;
    const std::string chosen = device == "auto" ? cameras.front() : device;
    if (device != "auto" && !std::filesystem::exists(chosen)) {
        std::string found;
        for (const auto& camera : cameras)
            found += (found.empty() ? "" : ", ") + camera;
        return {false, "camera.device = " + chosen + " does not exist",
                "set camera.device to one of: " + found + " (or auto)"};
    }
    if (const std::string problem = access_problem(chosen); !problem.empty()) {
        return {false, chosen + ": " + problem,
                "add your user to the video group: sudo usermod -aG video $USER, then log in "
                "again"};
    }
    return {
        true,
        chosen + " can be opened (" + std::to_string(cameras.size()) + " capture device(s) in all)",
        ""};
}

Check check_uinput() {
    const std::string path = "/dev/uinput";
    // Installed (the package, or cmake --install) or not (a build tree): the fix differs.
    const std::string modules_load = RAYPOINT_INSTALL_PREFIX "/lib/modules-load.d/raypoint.conf";
    const std::string udev_rule =
        RAYPOINT_INSTALL_PREFIX "/lib/udev/rules.d/70-raypoint-uinput.rules";
    if (!std::filesystem::exists(path)) {
        return {false, path + " does not exist (the uinput module is not loaded)",
                std::filesystem::exists(modules_load)
                    ? "sudo modprobe uinput (" + modules_load + " loads it at every boot)"
                    : "sudo modprobe uinput, and install packaging/modules-load.conf as " +
                          modules_load + " so it loads at boot (the raypoint package does)"};
    }
    if (const std::string problem = access_problem(path); !problem.empty()) {
        return {false, path + ": " + problem,
                std::filesystem::exists(udev_rule)
                    ? udev_rule +
                          " is installed: sudo udevadm trigger --sysname-match=uinput, then log "
                          "out and in again (the access is the active seat's user's)"
                    : "install packaging/70-raypoint-uinput.rules as " + udev_rule +
                          " (the raypoint package does; it gives the logged-in user access, "
                          "TAG+=\"uaccess\"), then sudo udevadm trigger and log in again"};
    }
    return {true, path + " is writable", ""};
}

Check check_service(std::string& control_path) {
    try {
        control_path = default_control_path();
    } catch (const ControlError& e) {
        return {false, e.what(), "run raypoint from your desktop session"};
    }
    try {
        const std::string reply = send_control(control_path, ControlCommand::status);
        return {
            true,
            "raypoint run answers on " + control_path + ": " + reply.substr(0, reply.find('\n')),
            ""};
    } catch (const ControlError&) {
        return {false, "raypoint run is not running (nothing answers on " + control_path + ")",
                "systemctl --user enable --now raypoint, then journalctl --user -u raypoint"};
    }
}

// Frames the trial cycles through: 40 of 640x480 are 37 MB BGR and 25 MB YUYV, more than a
// last-level cache holds, so each frame comes from memory as a camera's new buffer does. (One
// frame fed again stays cached, and on AMD Zen 3 that turns the filter's choice around.)
constexpr int trial_frames = 40;

// A camera-like 640x480 BGR frame: a lit wall (a gradient), a dark disk at `index`'s place,
// sensor noise. Only its size and format matter to the cost; the content keeps the loops honest.
cv::Mat drawn_frame(int index) {
    cv::Mat frame(480, 640, CV_8UC3);
    for (int y = 0; y < frame.rows; ++y) {
        auto* row = frame.ptr<cv::Vec3b>(y);
        for (int x = 0; x < frame.cols; ++x)
            row[x] = cv::Vec3b(cv::saturate_cast<uchar>(120 + x / 8), 150,
                               cv::saturate_cast<uchar>(200 - y / 6));
    }
    cv::circle(frame, {200 + 6 * index, 240}, 80, cv::Scalar(40, 60, 90), cv::FILLED);
    cv::Mat noise(frame.size(), CV_8UC3);
    cv::randu(noise, cv::Scalar::all(0), cv::Scalar::all(8));
    frame += noise;
    return frame;
}

// The trial `raypoint run` makes while INITIALIZING, on `frames` in turn (as many samples as a
// trial holds: about 0.1 s here). Returns the figures for one format.
template <typename FrameAt>
std::string measure_instructions(const core::Settings& settings, FrameAt frame_at,
                                 const char* format) {
    const core::InstructionSet best = core::best_instruction_set();
    core::Tracker tracker(settings);
    core::InstructionTrial trial(
        best, std::nullopt,
        core::InstructionTrial::max_candidates * core::InstructionTrial::max_samples);
    for (int i = 0; !trial.done(); ++i)
        process_in_trial(tracker, trial, frame_at(i, i * core::Timestamp{33'333}));  // 30 fps
    double chosen_us = 0.0;
    double widest_us = 0.0;
    for (int i = 0; i < trial.candidate_count(); ++i) {
        if (trial.candidate(i) == trial.chosen()) chosen_us = trial.median(i);
        if (trial.candidate(i) == core::StageInstructions::both(best)) widest_us = trial.median(i);
    }
    std::string text = std::string(format) + " " + describe_instructions(trial.chosen());
    if (!trial.measured()) return text;
    return text + " " + std::to_string(std::lround(chosen_us)) + " us (" +
           std::string(core::to_string(best)) + " for both " +
           std::to_string(std::lround(widest_us)) + " us)";
}

// The instruction sets `raypoint run` would use here: the configured set, or measured on drawn
// 640x480 frames as the daemon measures camera frames.
Check check_instructions(const config::Config& settings) {
    const core::InstructionSet best = core::best_instruction_set();
    if (const auto forced = config::forced_instruction_set(settings.instructions)) {
        const core::InstructionTrial trial(best, forced);
        // Clamped, as the daemon does (with a warning in its log): it runs, so not a failure.
        std::string what = describe_trial(trial, true);
        if (*forced > best) {
            what += "; " + std::string(core::to_string(*forced)) + " clamped: this CPU runs " +
                    std::string(core::to_string(best)) + " at most";
        }
        return {true, what, ""};
    }
    std::vector<cv::Mat> bgr;
    YuyvClip yuyv({640, 480}, 30.0);
    yuyv.reserve(trial_frames);
    for (int i = 0; i < trial_frames; ++i) {
        bgr.push_back(drawn_frame(i));
        yuyv.append(bgr.back());
    }
    const auto bgr_at = [&](int i, core::Timestamp timestamp) {
        const cv::Mat& image = bgr[static_cast<std::size_t>(i % trial_frames)];
        return core::FrameView{image.data,
                               image.cols,
                               image.rows,
                               static_cast<int>(image.step),
                               core::PixelFormat::bgr,
                               timestamp};
    };
    const auto yuyv_at = [&](int i, core::Timestamp timestamp) {
        return yuyv.view(i % trial_frames, timestamp);
    };
    return {true,
            measure_instructions(settings.core, bgr_at, "BGR") + "; " +
                measure_instructions(settings.core, yuyv_at, "YUYV") +
                " (median us a 640x480 frame)",
            ""};
}

}  // namespace

int doctor_command(std::span<const std::string_view> args) {
    if (!args.empty()) throw UsageError(std::string(args.front()) + ": doctor takes no options");
    int failures = 0;
    print_root_note();
    config::Config settings;
    print("config", check_config(settings), failures);
    print("camera", check_camera(settings), failures);
    print("uinput", check_uinput(), failures);
    print("cpu", check_instructions(settings), failures);
    std::string control_path;
    print("service", check_service(control_path), failures);
    std::printf(failures == 0 ? "all checks passed\n" : "%d check(s) failed\n", failures);
    return failures == 0 ? 0 : 1;
}

}  // namespace raypoint::daemon
