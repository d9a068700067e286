// SPDX-License-Identifier: MIT
// Camera setup without a camera: the choice of mode from what a driver offers, and the error
// messages with their hints (the /proc scan for who holds a device).

#include <fcntl.h>
#include <linux/videodev2.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/capture/camera_errors.hpp"
#include "raypoint/capture/camera_format.hpp"

namespace raypoint::daemon {

// Failures print "YUYV 640x480" rather than the bytes of the struct.
void PrintTo(const CameraMode& mode, std::ostream* out) {
    *out << describe(mode);
}

namespace {

constexpr std::uint32_t yuyv = V4L2_PIX_FMT_YUYV;
constexpr std::uint32_t mjpeg = V4L2_PIX_FMT_MJPEG;
const cv::Size working{160, 120};

CameraMode discrete(std::uint32_t fourcc, int width, int height) {
    return {fourcc, {width, height}, {}};
}

CameraMode stepwise(std::uint32_t fourcc, cv::Size min, cv::Size max, cv::Size step) {
    return {fourcc, {}, SizeRange{min, max, step}};
}

// A typical UVC webcam: both formats, sizes listed largest first.
std::vector<CameraMode> uvc_webcam() {
    return {discrete(yuyv, 640, 480),  discrete(yuyv, 352, 288), discrete(yuyv, 320, 240),
            discrete(yuyv, 176, 144),  discrete(yuyv, 160, 120), discrete(mjpeg, 1280, 720),
            discrete(mjpeg, 640, 480), discrete(mjpeg, 160, 120)};
}

TEST(ChooseFormat, YuyvOnlyTakesTheWorkingSizeWhenOffered) {
    EXPECT_EQ(choose_format(uvc_webcam(), working), discrete(yuyv, 160, 120));
}

TEST(ChooseFormat, YuyvTakesTheSmallestSizeAtLeastTheWorkingSize) {
    const std::vector<CameraMode> offered = {discrete(yuyv, 640, 480), discrete(yuyv, 320, 240),
                                             discrete(yuyv, 176, 144), discrete(yuyv, 1280, 720)};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 176, 144));
}

TEST(ChooseFormat, BothAxesMustReachTheWorkingSize) {
    // 200x100 is wider but not as tall as 160x120; 320x90 has more area and the same problem.
    const std::vector<CameraMode> offered = {discrete(yuyv, 200, 100), discrete(yuyv, 320, 90),
                                             discrete(yuyv, 640, 480)};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 640, 480));
}

TEST(ChooseFormat, TheWorkingSizeIsAParameter) {
    EXPECT_EQ(choose_format(uvc_webcam(), {320, 240}), discrete(yuyv, 320, 240));
    EXPECT_EQ(choose_format(uvc_webcam(), {321, 240}), discrete(yuyv, 352, 288));
    EXPECT_EQ(choose_format(uvc_webcam(), {353, 240}), discrete(yuyv, 640, 480));
}

TEST(ChooseFormat, YuyvIsPreferredOverASmallerMjpeg) {
    const std::vector<CameraMode> offered = {discrete(mjpeg, 160, 120), discrete(yuyv, 640, 480)};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 640, 480));
}

TEST(ChooseFormat, MjpegOnly) {
    const std::vector<CameraMode> offered = {discrete(mjpeg, 1920, 1080), discrete(mjpeg, 640, 480),
                                             discrete(mjpeg, 320, 240)};
    EXPECT_EQ(choose_format(offered, working), discrete(mjpeg, 320, 240));
}

TEST(ChooseFormat, MjpegWhenYuyvIsTooSmall) {
    const std::vector<CameraMode> offered = {discrete(yuyv, 80, 60), discrete(mjpeg, 640, 480)};
    EXPECT_EQ(choose_format(offered, working), discrete(mjpeg, 640, 480));
}

TEST(ChooseFormat, JpegCountsAsMjpeg) {
    const std::vector<CameraMode> offered = {discrete(V4L2_PIX_FMT_JPEG, 320, 240)};
    EXPECT_EQ(choose_format(offered, working), discrete(V4L2_PIX_FMT_JPEG, 320, 240));
}

TEST(ChooseFormat, OddYuyvWidthsAreSkipped) {
    // Two pixels share one U and V: an odd-width YUYV frame has no whole last pair.
    const std::vector<CameraMode> offered = {discrete(yuyv, 161, 120), discrete(yuyv, 320, 240)};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 320, 240));
}

TEST(ChooseFormat, SameAreaPrefersTheNarrower) {
    const std::vector<CameraMode> offered = {discrete(yuyv, 240, 160), discrete(yuyv, 160, 240)};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 160, 240));
}

TEST(ChooseFormat, StepwiseLandsOnTheGrid) {
    // 48 + 7 * 16 = 160, 32 + 11 * 8 = 120: vivid-like ranges hit the working size exactly.
    const std::vector<CameraMode> offered = {stepwise(yuyv, {48, 32}, {1920, 1080}, {16, 8})};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 160, 120));
}

TEST(ChooseFormat, StepwiseRoundsUpToTheNextStep) {
    // Widths 100, 107, ..., 163 (odd, so 170); heights 100, 110, 120.
    const std::vector<CameraMode> offered = {stepwise(yuyv, {100, 100}, {640, 480}, {7, 10})};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 170, 120));
}

TEST(ChooseFormat, StepwiseMinimumAboveTheWorkingSize) {
    const std::vector<CameraMode> offered = {stepwise(yuyv, {320, 240}, {640, 480}, {2, 2})};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 320, 240));
}

TEST(ChooseFormat, ContinuousGivesTheWorkingSizeExactly) {
    const std::vector<CameraMode> offered = {stepwise(mjpeg, {1, 1}, {4096, 2160}, {1, 1})};
    EXPECT_EQ(choose_format(offered, {161, 121}), discrete(mjpeg, 161, 121));
}

TEST(ChooseFormat, StepwiseMaximumBelowTheWorkingSize) {
    const std::vector<CameraMode> offered = {stepwise(yuyv, {16, 16}, {128, 96}, {16, 16})};
    EXPECT_EQ(choose_format(offered, working), std::nullopt);
}

TEST(ChooseFormat, StepwiseWithAZeroStepDoesNotHang) {
    const std::vector<CameraMode> offered = {stepwise(yuyv, {64, 64}, {640, 480}, {0, 0})};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 160, 120));
}

TEST(ChooseFormat, StepwiseAndDiscreteMixed) {
    const std::vector<CameraMode> offered = {discrete(yuyv, 640, 480),
                                             stepwise(yuyv, {176, 144}, {352, 288}, {16, 16})};
    EXPECT_EQ(choose_format(offered, working), discrete(yuyv, 176, 144));
}

TEST(ChooseFormat, NoneUsable) {
    EXPECT_EQ(choose_format({}, working), std::nullopt);
    // GREY (TODO: needs a core grey format), NV12, H.264: not formats the core or we decode.
    const std::vector<CameraMode> others = {discrete(V4L2_PIX_FMT_GREY, 640, 480),
                                            discrete(V4L2_PIX_FMT_NV12, 640, 480),
                                            discrete(V4L2_PIX_FMT_H264, 1920, 1080)};
    EXPECT_EQ(choose_format(others, working), std::nullopt);
    const std::vector<CameraMode> too_small = {discrete(yuyv, 128, 96), discrete(mjpeg, 80, 60)};
    EXPECT_EQ(choose_format(too_small, working), std::nullopt);
}

TEST(ChooseFormat, Describe) {
    EXPECT_EQ(fourcc_name(yuyv), "YUYV");
    EXPECT_EQ(fourcc_name(mjpeg), "MJPG");
    EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_Y16), "Y16");
    EXPECT_EQ(describe(discrete(yuyv, 640, 480)), "YUYV 640x480");
    EXPECT_EQ(describe(stepwise(mjpeg, {16, 16}, {1920, 1080}, {8, 8})),
              "MJPG 16x16..1920x1080 step 8x8");
}

// A file of our own, held open for the test: find_file_holders must find this process.
class HeldFile : public ::testing::Test {
  protected:
    void SetUp() override {
        path_ =
            std::filesystem::temp_directory_path() / ("raypoint-held-" + std::to_string(getpid()));
        std::ofstream(path_) << "x";
        fd_ = open(path_.c_str(), O_RDONLY | O_CLOEXEC);
        ASSERT_GE(fd_, 0);
        std::ifstream comm("/proc/self/comm");
        std::getline(comm, comm_);
    }
    void TearDown() override {
        if (fd_ >= 0) close(fd_);
        std::filesystem::remove(path_);
        std::filesystem::remove(link_);
    }
    std::filesystem::path path_;
    std::filesystem::path link_;
    int fd_ = -1;
    std::string comm_;
};

bool has_pid(const std::vector<FileHolder>& holders, int pid, const std::string& name) {
    for (const auto& holder : holders) {
        if (holder.pid == pid && holder.name == name) return true;
    }
    return false;
}

TEST_F(HeldFile, ScanFindsThisProcess) {
    EXPECT_TRUE(has_pid(find_file_holders(path_.string()), getpid(), comm_));
}

TEST_F(HeldFile, ScanResolvesALinkLikeByIdNames) {
    link_ = path_.string() + "-link";
    std::filesystem::create_symlink(path_, link_);
    EXPECT_TRUE(has_pid(find_file_holders(link_.string()), getpid(), comm_));
}

TEST_F(HeldFile, ScanFindsNoOneForAClosedFile) {
    close(fd_);
    fd_ = -1;
    EXPECT_FALSE(has_pid(find_file_holders(path_.string()), getpid(), comm_));
}

TEST_F(HeldFile, BusyNamesTheOtherHolderNotUs) {
    // A child holds the file too (fork keeps our descriptor and our name); we hold it as well,
    // as the daemon does when S_FMT says EBUSY, and must not be named.
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const char byte = 1;
        if (write(ready[1], &byte, 1) != 1) _exit(1);
        pause();
        _exit(0);
    }
    char byte = 0;
    ASSERT_EQ(read(ready[0], &byte, 1), 1);
    const std::string message = camera_error_message(path_.string(), "VIDIOC_REQBUFS", EBUSY);
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    close(ready[0]);
    close(ready[1]);
    EXPECT_NE(message.find(path_.string() + ": VIDIOC_REQBUFS: " + std::strerror(EBUSY)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("another program holds the camera"), std::string::npos) << message;
    EXPECT_NE(message.find(comm_ + " (pid " + std::to_string(child) + ")"), std::string::npos)
        << message;
    EXPECT_EQ(message.find("(pid " + std::to_string(getpid()) + ")"), std::string::npos) << message;
}

TEST(CameraErrorMessage, BusyWithNoHolderFound) {
    const std::string message = camera_error_message("/nonexistent/video9", "open", EBUSY);
    EXPECT_NE(message.find("another program holds the camera"), std::string::npos) << message;
}

TEST(CameraErrorMessage, AccessDeniedSaysTheVideoGroup) {
    const std::string message = camera_error_message("/dev/video0", "open", EACCES);
    EXPECT_EQ(message,
              "/dev/video0: open: " + std::string(std::strerror(EACCES)) +
                  "; add your user to the 'video' group (sudo usermod -aG video $USER, then log "
                  "in again)");
}

TEST(CameraErrorMessage, MissingListsTheDevicesThatExist) {
    const std::string message = camera_error_message(
        "/dev/video7", "open", ENOENT, {"/dev/video0 (Webcam)", "/dev/video2 (vivid)"});
    EXPECT_NE(message.find("/dev/video0 (Webcam), /dev/video2 (vivid)"), std::string::npos)
        << message;
    const std::string none = camera_error_message("/dev/video7", "open", ENOENT);
    EXPECT_NE(none.find("there is no video capture device"), std::string::npos) << none;
}

TEST(CameraErrorMessage, OtherErrorsAreJustNamed) {
    EXPECT_EQ(camera_error_message("/dev/video0", "VIDIOC_S_FMT", EINVAL),
              "/dev/video0: VIDIOC_S_FMT: " + std::string(std::strerror(EINVAL)));
}

}  // namespace
}  // namespace raypoint::daemon
