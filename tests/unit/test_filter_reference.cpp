// SPDX-License-Identifier: MIT
// The Poisson-disk filter and subsampling (paper 4.1) against a plain reference written from
// the documented definition: working pixel centre round((i + 0.5) * N / n - 0.5), taps at
// round(tap * radius) with radius = filter_radius * width / 640, clamped to the frame, summed
// and divided with rounding. The core's SIMD and clamped paths must match it exactly, in BGR
// and in YUYV, at sizes that take each path, with every instruction set this CPU runs; the grey
// image computed alongside must equal OpenCV's cv::COLOR_BGR2GRAY of the colour image.

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/core/preprocess.hpp"

namespace {

using raypoint::core::FrameView;
using raypoint::core::InstructionSet;
using raypoint::core::PixelFormat;
using raypoint::core::Preprocessor;
using raypoint::core::PreprocessSettings;

int centre(int index, int working, int input) {
    return static_cast<int>(std::lround((index + 0.5) * input / working - 0.5));
}

std::uint8_t clamp_byte(int v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0, 255));
}

// Reference: returns the working BGR image for a BGR or YUYV frame.
cv::Mat reference(const cv::Mat& frame, PixelFormat format, int width, cv::Size working,
                  double filter_radius) {
    const auto& taps = raypoint::core::poisson_disk_taps();
    const double radius = filter_radius * width / 640.0;
    const int n = static_cast<int>(taps.size());
    cv::Mat out(working, CV_8UC3);
    for (int y = 0; y < working.height; ++y) {
        for (int x = 0; x < working.width; ++x) {
            int sum[3] = {0, 0, 0};
            for (const auto& tap : taps) {
                const int column = std::clamp(
                    centre(x, working.width, width) + static_cast<int>(std::lround(tap.x * radius)),
                    0, width - 1);
                const int row = std::clamp(centre(y, working.height, frame.rows) +
                                               static_cast<int>(std::lround(tap.y * radius)),
                                           0, frame.rows - 1);
                const std::uint8_t* line = frame.ptr<std::uint8_t>(row);
                if (format == PixelFormat::bgr) {
                    for (int c = 0; c < 3; ++c)
                        sum[c] += line[column * 3 + c];
                } else {
                    const std::uint8_t* pair = line + (column / 2) * 4;
                    sum[0] += pair[(column % 2) * 2];  // Y
                    sum[1] += pair[1];                 // U
                    sum[2] += pair[3];                 // V
                }
            }
            auto& pixel = out.at<cv::Vec3b>(y, x);
            if (format == PixelFormat::bgr) {
                for (int c = 0; c < 3; ++c)
                    pixel[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
            } else {
                const int luma = (sum[0] + n / 2) / n - 16;
                const int u = (sum[1] + n / 2) / n - 128;
                const int v = (sum[2] + n / 2) / n - 128;
                const int scaled = 298 * luma + 128;
                pixel[0] = clamp_byte((scaled + 516 * u) >> 8);
                pixel[1] = clamp_byte((scaled - 100 * u - 208 * v) >> 8);
                pixel[2] = clamp_byte((scaled + 409 * v) >> 8);
            }
        }
    }
    return out;
}

// The sets this CPU can run: scalar and SSE2 always on x86-64, AVX2 when it has it.
std::vector<InstructionSet> runnable_sets() {
    std::vector<InstructionSet> sets{InstructionSet::scalar};
    const InstructionSet best = raypoint::core::best_instruction_set();
    if (best != InstructionSet::scalar) sets.push_back(InstructionSet::sse2);
    if (best == InstructionSet::avx2) sets.push_back(InstructionSet::avx2);
    return sets;
}

// `frame`: size.height rows of the frame's bytes, any step.
void expect_frame_matches_reference(const cv::Mat& frame, cv::Size size, PixelFormat format,
                                    double filter_radius = 5.0) {
    PreprocessSettings settings;
    settings.filter_radius = filter_radius;
    const cv::Mat expected =
        reference(frame, format, size.width, cv::Size(settings.work_width, settings.work_height),
                  filter_radius);
    cv::Mat expected_grey;
    cv::cvtColor(expected, expected_grey, cv::COLOR_BGR2GRAY);
    for (const InstructionSet set : runnable_sets()) {
        Preprocessor preprocessor(settings, raypoint::core::StageInstructions::both(set));
        ASSERT_TRUE(preprocessor.process(FrameView{frame.data, size.width, size.height,
                                                   static_cast<int>(frame.step), format, 0}));
        const std::string where =
            std::to_string(size.width) + "x" + std::to_string(size.height) +
            (format == PixelFormat::bgr ? " BGR " : " YUYV ") + std::string(to_string(set)) +
            " step " + std::to_string(frame.step) + " radius " + std::to_string(filter_radius);
        cv::Mat difference;
        cv::absdiff(preprocessor.color(), expected, difference);
        EXPECT_EQ(cv::countNonZero(difference.reshape(1)), 0) << where;
        cv::absdiff(preprocessor.gray(), expected_grey, difference);
        EXPECT_EQ(cv::countNonZero(difference), 0) << where << " grey";
    }
}

int row_bytes(cv::Size size, PixelFormat format) {
    return format == PixelFormat::bgr ? size.width * 3 : size.width * 2;
}

void expect_matches_reference(cv::Size size, PixelFormat format, double filter_radius = 5.0) {
    cv::Mat frame(size.height, row_bytes(size, format), CV_8U);
    cv::randu(frame, 0, 256);
    expect_frame_matches_reference(frame, size, format, filter_radius);
    // Rows further apart than their bytes (a padded buffer), by an odd count.
    cv::Mat padded(size.height, row_bytes(size, format) + 13, CV_8U);
    cv::randu(padded, 0, 256);
    expect_frame_matches_reference(padded.colRange(0, row_bytes(size, format)), size, format,
                                   filter_radius);
}

// 640, 1280, 1920: integer scales (SIMD interior); 642 and 320: the clamped path; 160 and
// 250: borders of other widths (1:1, and a scale whose centres step unevenly).
TEST(FilterReference, BgrMatchesExactly) {
    for (const cv::Size size :
         {cv::Size(640, 480), cv::Size(1280, 720), cv::Size(642, 482), cv::Size(320, 240),
          cv::Size(1920, 1080), cv::Size(160, 120), cv::Size(250, 190)}) {
        expect_matches_reference(size, PixelFormat::bgr);
    }
}

TEST(FilterReference, YuyvMatchesExactly) {
    for (const cv::Size size :
         {cv::Size(640, 480), cv::Size(1280, 720), cv::Size(642, 482), cv::Size(320, 240),
          cv::Size(1920, 1080), cv::Size(160, 120), cv::Size(250, 190)}) {
        expect_matches_reference(size, PixelFormat::yuyv);
    }
}

// The largest radius the settings allow: ten clamped columns on each side at 640 wide, in
// groups of four and a partial one, and at 160 wide more than a quarter of the row.
TEST(FilterReference, WideRadiusBordersMatchExactly) {
    for (const PixelFormat format : {PixelFormat::bgr, PixelFormat::yuyv}) {
        for (const cv::Size size : {cv::Size(640, 480), cv::Size(160, 120), cv::Size(642, 482)})
            expect_matches_reference(size, format, 40.0);
    }
}

// The vector kernels load whole 8- and 16-byte groups around each tap: none may read before
// the frame's first byte or past its last. Each frame here lies between inaccessible pages (a
// read outside it ends the test with SIGSEGV), once against the page after and once against
// the page before.
TEST(FilterReference, ReadsNothingOutsideTheFrame) {
    const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    for (const PixelFormat format : {PixelFormat::bgr, PixelFormat::yuyv}) {
        for (const cv::Size size :
             {cv::Size(640, 480), cv::Size(320, 240), cv::Size(1280, 720), cv::Size(642, 482)}) {
            const std::size_t bytes =
                static_cast<std::size_t>(row_bytes(size, format)) * size.height;
            const std::size_t span = (bytes + page - 1) / page * page;
            void* mapping =
                mmap(nullptr, span + 2 * page, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            ASSERT_NE(mapping, MAP_FAILED) << "mmap: " << std::strerror(errno);
            auto* inside = static_cast<std::uint8_t*>(mapping) + page;
            ASSERT_EQ(mprotect(inside, span, PROT_READ | PROT_WRITE), 0)
                << "mprotect: " << std::strerror(errno);
            for (std::uint8_t* start : {inside + span - bytes, inside}) {
                cv::Mat frame(size.height, row_bytes(size, format), CV_8U, start);
                cv::randu(frame, 0, 256);
                expect_frame_matches_reference(frame, size, format);
            }
            munmap(mapping, span + 2 * page);
        }
    }
}

// The edge and difference images too: two frames through each instruction set, for both edge
// and movement sources, against the scalar path.
TEST(FilterReference, EveryInstructionSetGivesTheSameImages) {
    const cv::Size size(640, 480);
    std::vector<cv::Mat> frames(2, cv::Mat(size, CV_8UC3));
    for (auto& frame : frames) {
        frame = cv::Mat(size, CV_8UC3);
        cv::randu(frame, 0, 256);
        cv::GaussianBlur(frame, frame, {0, 0}, 2.0);  // random noise alone has no edges to keep
    }
    for (const auto source :
         {raypoint::core::EdgeSource::luma, raypoint::core::EdgeSource::max_channel}) {
        PreprocessSettings settings;
        settings.edge_source = source;
        settings.movement_source = source;
        settings.edge_threshold = 8;
        std::vector<std::unique_ptr<Preprocessor>> runs;
        for (const InstructionSet set : runnable_sets()) {
            runs.push_back(std::make_unique<Preprocessor>(
                settings, raypoint::core::StageInstructions::both(set)));
            for (const auto& frame : frames) {
                ASSERT_TRUE(runs.back()->process(FrameView{frame.data, size.width, size.height,
                                                           static_cast<int>(frame.step),
                                                           PixelFormat::bgr, 0}));
            }
        }
        const Preprocessor& scalar = *runs.front();
        ASSERT_GT(cv::countNonZero(scalar.edges()), 100);
        ASSERT_GT(cv::countNonZero(scalar.difference()), 100);
        for (std::size_t i = 1; i < runs.size(); ++i) {
            const std::string where(to_string(runnable_sets()[i]));
            for (const auto& [mine, theirs] :
                 {std::pair{&runs[i]->magnitude(), &scalar.magnitude()},
                  std::pair{&runs[i]->edges(), &scalar.edges()},
                  std::pair{&runs[i]->difference(), &scalar.difference()}}) {
                cv::Mat difference;
                cv::absdiff(*mine, *theirs, difference);
                EXPECT_EQ(cv::countNonZero(difference), 0) << where;
            }
            EXPECT_EQ(runs[i]->movement(), scalar.movement()) << where;
        }
    }
}

}  // namespace
