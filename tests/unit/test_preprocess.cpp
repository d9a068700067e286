// SPDX-License-Identifier: MIT
// Frame preprocessing (paper 4.1), each step against hand-computed values.

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {
namespace {

using test::bgr_view;
using test::identity_settings;
using test::to_yuyv;
using test::uniform;
using test::Yuyv;

// Left half 0, right half `value`, split at input column width / 2.
cv::Mat vertical_step(cv::Size size, int value) {
    cv::Mat frame = uniform(size, cv::Vec3b(0, 0, 0));
    frame.colRange(size.width / 2, size.width).setTo(cv::Scalar::all(value));
    return frame;
}

TEST(PoissonDiskTaps, SixteenTapsInTheUnitDiskWithTheCentreAndSpacing) {
    const auto& taps = poisson_disk_taps();
    ASSERT_EQ(taps.size(), 16U);
    EXPECT_EQ(taps[0], cv::Point2f(0.0F, 0.0F));
    double nearest = 1e9;
    for (std::size_t i = 0; i < taps.size(); ++i) {
        EXPECT_LE(std::hypot(taps[i].x, taps[i].y), 1.0) << "tap " << i;
        for (std::size_t j = 0; j < i; ++j) {
            nearest = std::min(nearest, std::hypot(static_cast<double>(taps[i].x - taps[j].x),
                                                   static_cast<double>(taps[i].y - taps[j].y)));
        }
    }
    EXPECT_GT(nearest, 0.3);
}

TEST(PoissonDiskTaps, DeterministicOffsets) {
    const auto& first = poisson_disk_taps();
    const auto copy = first;
    EXPECT_EQ(&poisson_disk_taps(), &first);
    EXPECT_EQ(poisson_disk_taps(), copy);
    // The hand-computed filter values below depend on these: lround(tap.x * 5), the horizontal
    // input offsets at radius 5. Platform independent (SplitMix, not <random>).
    const std::array<int, 16> dx5{0, -5, 5, -1, 1, 2, -2, -4, -1, 2, -3, 3, -1, 0, -4, 2};
    for (std::size_t t = 0; t < dx5.size(); ++t) {
        EXPECT_EQ(std::lround(first[t].x * 5.0F), dx5[t]) << "tap " << t;
    }
}

TEST(Filter, UniformFrameKeepsItsColourExactly) {
    Preprocessor pre(PreprocessSettings{});
    const cv::Mat frame = uniform({640, 480}, cv::Vec3b(10, 20, 30));
    ASSERT_TRUE(pre.process(bgr_view(frame)));
    ASSERT_EQ(pre.color().size(), cv::Size(160, 120));
    // Each channel: (16 * v + 8) / 16 = v, integer division.
    cv::Mat wrong;
    cv::compare(pre.color().reshape(1), uniform({160, 120}, cv::Vec3b(10, 20, 30)).reshape(1),
                wrong, cv::CMP_NE);
    EXPECT_EQ(cv::countNonZero(wrong), 0);
    // Grey: 0.299 * 30 + 0.587 * 20 + 0.114 * 10 = 8.97 + 11.74 + 1.14 = 21.85 -> 22.
    EXPECT_EQ(pre.gray().at<std::uint8_t>(60, 80), 22);
}

// Expected working values across a vertical 0 | 200 step, from the tap table above.
// The working column x samples input column c = round((x + 0.5) * W / 160 - 0.5), each tap at
// c + round(tap.x * r) with r = 5 * W / 640, and the output is (200 * taps_right + 8) / 16.
//  W=640  : c = 4x + 2, r = 5.   x=78: c=314, 314+5 = 319 < 320             -> 0
//           x=79: c=318, taps with dx >= 2: {5,2,2,3,2} = 5    -> (1000 + 8) / 16 = 63
//           x=80: c=322, taps with dx <= -3 on the left: {-5,-4,-3,-4} = 4, so 12 right
//                                                               -> (2400 + 8) / 16 = 150
//           x=81: c=326, 326-5 = 321 >= 320                      -> 200
//  W=1280 : c = 8x + 4, r = 10, dx = round(tap.x * 10) = {0,-10,10,-2,3,4,-4,-7,-1,5,-5,7,
//           -3,0,-7,5}. x=79: c=636, dx >= 4: {10,4,5,7,5} = 5 -> 63. x=80: c=644,
//           dx <= -5: {-10,-7,-5,-7} = 4 left -> 150. The filter scales with the frame.
//  W=320  : c = 2x + 1, r = 2.5, dx = {0,-2,2,-1,1,1,-1,-2,0,1,-1,2,-1,0,-2,1}
//           x=79: c=159, dx >= 1: {2,1,1,1,2,1} = 6 -> (1200 + 8) / 16 = 75
//           x=80: c=161, dx <= -2 left: {-2,-2,-2} = 3, 13 right -> (2600 + 8) / 16 = 163
struct StepCase {
    cv::Size input;
    int at_79;
    int at_80;
};

void PrintTo(const StepCase& c, std::ostream* os) {
    *os << c.input.width << "x" << c.input.height;
}

class FilterStep : public ::testing::TestWithParam<StepCase> {};

TEST_P(FilterStep, FarPixelsKeepTheirValueNearOnesBlend) {
    const StepCase c = GetParam();
    Preprocessor pre(PreprocessSettings{});
    ASSERT_TRUE(pre.process(bgr_view(vertical_step(c.input, 200))));
    const cv::Mat& colour = pre.color();
    ASSERT_EQ(colour.size(), cv::Size(160, 120));
    for (int y = 0; y < 120; y += 7) {
        for (int x = 0; x < 160; ++x) {
            const int value = colour.at<cv::Vec3b>(y, x)[1];
            if (x <= 78) {
                ASSERT_EQ(value, 0) << "x=" << x << " y=" << y;
            } else if (x == 79) {
                ASSERT_EQ(value, c.at_79) << "y=" << y;
            } else if (x == 80) {
                ASSERT_EQ(value, c.at_80) << "y=" << y;
            } else {
                ASSERT_EQ(value, 200) << "x=" << x << " y=" << y;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(InputSizes, FilterStep,
                         ::testing::Values(StepCase{{640, 480}, 63, 150},
                                           StepCase{{320, 240}, 75, 163},
                                           StepCase{{1280, 720}, 63, 150}));

TEST(Filter, WorkingSizeFromSettings) {
    PreprocessSettings settings;
    settings.work_width = 80;
    settings.work_height = 60;
    Preprocessor pre(settings);
    ASSERT_TRUE(pre.process(bgr_view(vertical_step({640, 480}, 200))));
    for (const cv::Mat* image :
         {&pre.color(), &pre.gray(), &pre.magnitude(), &pre.edges(), &pre.difference()}) {
        EXPECT_EQ(image->size(), cv::Size(80, 60));
    }
    // c = round((x + 0.5) * 8 - 0.5) = 8x + 4, r = 5. x=38: 308+5 < 320 -> 0.
    // x=39: c=316, dx >= 4: {5} = 1 -> (200 + 8) / 16 = 13.
    // x=40: c=324, dx <= -5: {-5} = 1 left, 15 right -> (3000 + 8) / 16 = 188. x=41: 328-5 -> 200.
    const auto at = [&](int x) { return pre.color().at<cv::Vec3b>(30, x)[0]; };
    EXPECT_EQ(at(38), 0);
    EXPECT_EQ(at(39), 13);
    EXPECT_EQ(at(40), 188);
    EXPECT_EQ(at(41), 200);
}

TEST(Input, RejectsUnreadableFrames) {
    Preprocessor pre(PreprocessSettings{});
    const cv::Mat frame = uniform({640, 480}, cv::Vec3b(1, 2, 3));
    FrameView view = bgr_view(frame);
    view.data = nullptr;
    EXPECT_FALSE(pre.process(view));
    const cv::Mat small = uniform({159, 120}, cv::Vec3b(1, 2, 3));
    EXPECT_FALSE(pre.process(bgr_view(small)));
    view = bgr_view(frame);
    view.stride = 640 * 3 - 1;
    EXPECT_FALSE(pre.process(view));
    EXPECT_EQ(pre.color().at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));  // nothing processed
    EXPECT_TRUE(pre.process(bgr_view(frame)));
    EXPECT_EQ(pre.color().at<cv::Vec3b>(0, 0), cv::Vec3b(1, 2, 3));
}

// BT.601 limited range, as the Preprocessor decodes: Y=81, U=90, V=240 -> Y'=65, U'=-38,
// V'=112; s = 298 * 65 + 128 = 19498.
//   B = (s + 516 * -38) >> 8 = -110 >> 8 = -1 -> 0
//   G = (s - 100 * -38 - 208 * 112) >> 8 = 2 >> 8 = 0
//   R = (s + 409 * 112) >> 8 = 65306 >> 8 = 255
Yuyv uniform_yuyv(int width, int height, int stride, std::uint8_t y, std::uint8_t u,
                  std::uint8_t v) {
    Yuyv out;
    out.width = width;
    out.height = height;
    out.stride = stride;
    out.bytes.assign(static_cast<std::size_t>(stride) * height, 0xEE);  // padding: garbage
    for (int row = 0; row < height; ++row) {
        std::uint8_t* p = out.bytes.data() + static_cast<std::ptrdiff_t>(row) * stride;
        for (int x = 0; x < width; x += 2) {
            p[x * 2] = y;
            p[x * 2 + 1] = u;
            p[x * 2 + 2] = y;
            p[x * 2 + 3] = v;
        }
    }
    return out;
}

TEST(Input, YuyvRedDecodesToBgrRed) {
    Preprocessor pre(PreprocessSettings{});
    ASSERT_TRUE(pre.process(uniform_yuyv(640, 480, 1280, 81, 90, 240).view()));
    for (const cv::Point p : {cv::Point(0, 0), cv::Point(80, 60), cv::Point(159, 119)}) {
        const cv::Vec3b bgr = pre.color().at<cv::Vec3b>(p);
        EXPECT_NEAR(bgr[0], 0, 2);
        EXPECT_NEAR(bgr[1], 0, 2);
        EXPECT_NEAR(bgr[2], 255, 2);
    }
}

TEST(Input, YuyvRejectsOddWidthAndAcceptsPaddedRows) {
    Preprocessor pre(PreprocessSettings{});
    EXPECT_FALSE(pre.process(uniform_yuyv(641, 480, 1284, 81, 90, 240).view()));
    // Rows padded by 96 garbage bytes decode exactly as unpadded ones.
    ASSERT_TRUE(pre.process(uniform_yuyv(640, 480, 1280 + 96, 81, 90, 240).view()));
    const cv::Mat padded = pre.color().clone();
    ASSERT_TRUE(pre.process(uniform_yuyv(640, 480, 1280, 81, 90, 240).view()));
    EXPECT_EQ(cv::norm(padded, pre.color(), cv::NORM_INF), 0.0);
    EXPECT_NEAR(padded.at<cv::Vec3b>(60, 80)[2], 255, 2);
}

TEST(Input, YuyvTakesEachPixelsOwnLuma) {
    // Even columns Y=16 (black), odd Y=235 (white), U=V=128: with the identity filter working
    // pixel x is input pixel x. (298 * 0 + 128) >> 8 = 0 and (298 * 219 + 128) >> 8 = 255.
    Yuyv frame = uniform_yuyv(160, 120, 320, 16, 128, 128);
    for (int row = 0; row < 120; ++row) {
        for (int x = 1; x < 160; x += 2)
            frame.bytes[row * 320 + x * 2] = 235;
    }
    Preprocessor pre(identity_settings());
    ASSERT_TRUE(pre.process(frame.view()));
    EXPECT_EQ(pre.color().at<cv::Vec3b>(10, 40), cv::Vec3b(0, 0, 0));
    EXPECT_EQ(pre.color().at<cv::Vec3b>(10, 41), cv::Vec3b(255, 255, 255));
}

// A grey vertical step of height h at column 80 of a 160x120 input read through the identity
// filter. The 3x3 Sobel x kernel [-1 0 1; -2 0 2; -1 0 1] sees 0 on its left column and h on
// its right one only at columns 79 and 80: gx = (1 + 2 + 1) * h = 4h; gy = 0 everywhere.
cv::Mat sobel_magnitude_of_step(int h, int threshold, cv::Mat* edges = nullptr) {
    PreprocessSettings settings = identity_settings();
    settings.edge_threshold = threshold;
    Preprocessor pre(settings);
    cv::Mat frame = uniform({160, 120}, cv::Vec3b(40, 40, 40));
    frame.colRange(80, 160).setTo(cv::Scalar::all(40 + h));
    EXPECT_TRUE(pre.process(bgr_view(frame)));
    if (edges != nullptr) *edges = pre.edges().clone();
    return pre.magnitude().clone();
}

TEST(Edges, SobelMagnitudeOfAStepIsFourTimesItsHeight) {
    for (const int h : {10, 30, 33, 63, 64, 100}) {
        const cv::Mat magnitude = sobel_magnitude_of_step(h, 128);
        const int expected = std::min(255, 4 * h);  // 100 -> 400 saturates to 255
        for (int x = 0; x < 160; ++x) {
            const int want = (x == 79 || x == 80) ? expected : 0;
            ASSERT_EQ(magnitude.at<std::uint8_t>(50, x), want) << "h=" << h << " x=" << x;
        }
        EXPECT_EQ(cv::countNonZero(magnitude), 2 * 120) << "h=" << h;
    }
}

TEST(Edges, EdgePixelsAreThoseOverTheThreshold) {
    cv::Mat edges;
    // 4 * 32 = 128 is not over 128; 4 * 33 = 132 is. Edge pixels carry their magnitude.
    sobel_magnitude_of_step(32, 128, &edges);
    EXPECT_EQ(cv::countNonZero(edges), 0);
    const cv::Mat magnitude = sobel_magnitude_of_step(33, 128, &edges);
    EXPECT_EQ(cv::countNonZero(edges), 240);
    EXPECT_EQ(edges.at<std::uint8_t>(7, 79), 132);
    EXPECT_EQ(edges.at<std::uint8_t>(7, 80), 132);
    EXPECT_EQ(edges.at<std::uint8_t>(7, 78), 0);
    cv::Mat differs;
    cv::compare(edges, magnitude, differs, cv::CMP_NE);
    EXPECT_EQ(cv::countNonZero(differs), 0);
    // The threshold is a setting: 4 * 30 = 120 is over 100.
    sobel_magnitude_of_step(30, 100, &edges);
    EXPECT_EQ(cv::countNonZero(edges), 240);
}

TEST(Edges, MagnitudeIsTheEuclideanNormAtACorner) {
    // A bright quadrant (x >= 80, y >= 60, +20). At (80, 60) the 3x3 window is
    //   row 59: 0 0 0 / row 60: 0 h h / row 61: 0 h h
    // gx = (0 - 0) + 2 (h - 0) + (h - 0) = 3h, gy = (0 + 2h + h) - 0 = 3h,
    // |g| = sqrt(18) h = 84.85 for h = 20 (|gx| + |gy| would be 120).
    Preprocessor pre(identity_settings());
    cv::Mat frame = uniform({160, 120}, cv::Vec3b(40, 40, 40));
    frame(cv::Rect(80, 60, 80, 60)).setTo(cv::Scalar::all(60));
    ASSERT_TRUE(pre.process(bgr_view(frame)));
    const int corner = pre.magnitude().at<std::uint8_t>(60, 80);
    EXPECT_GE(corner, 84);
    EXPECT_LE(corner, 85);
}

TEST(Edges, MaxChannelSeesABlueOnlyStepThatLumaMisses) {
    // Left BGR (0, 100, 100), right (200, 61, 100). OpenCV's grey is
    // (4899 R + 9617 G + 1868 B + 8192) >> 14:
    //   left  = (489900 + 961700 + 0 + 8192) >> 14 = 1459792 >> 14 = 89
    //   right = (489900 + 586637 + 373600 + 8192) >> 14 = 1458329 >> 14 = 89
    // Equal grey: the luma Sobel is 0. Blue steps by 200: 4 * 200 = 800 -> 255.
    cv::Mat frame = uniform({160, 120}, cv::Vec3b(0, 100, 100));
    frame.colRange(80, 160).setTo(cv::Scalar(200, 61, 100));
    PreprocessSettings settings = identity_settings();
    settings.edge_source = EdgeSource::luma;
    Preprocessor luma(settings);
    settings.edge_source = EdgeSource::max_channel;
    Preprocessor max_channel(settings);
    ASSERT_TRUE(luma.process(bgr_view(frame)));
    ASSERT_TRUE(max_channel.process(bgr_view(frame)));
    EXPECT_EQ(luma.gray().at<std::uint8_t>(10, 10), 89);
    EXPECT_EQ(luma.gray().at<std::uint8_t>(10, 150), 89);
    EXPECT_EQ(cv::countNonZero(luma.magnitude()), 0);
    EXPECT_EQ(cv::countNonZero(luma.edges()), 0);
    EXPECT_EQ(max_channel.magnitude().at<std::uint8_t>(10, 79), 255);
    EXPECT_EQ(max_channel.magnitude().at<std::uint8_t>(10, 80), 255);
    EXPECT_EQ(cv::countNonZero(max_channel.edges()), 240);
}

}  // namespace
}  // namespace raypoint::core
