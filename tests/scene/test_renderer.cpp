// SPDX-License-Identifier: MIT
// The scene renderer's promises: exact truth, determinism, and each condition doing what it says.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "raypoint/scene/json.hpp"
#include "raypoint/scene/renderer.hpp"
#include "renderer_testing.hpp"

namespace {

using namespace raypoint::scene;
using raypoint::scene::render_testing::mean_grey;
using raypoint::scene::render_testing::still;

// Truth recomputed from the mask with plain loops (independent of the renderer's code).
Truth recount(const cv::Mat& mask) {
    Truth t;
    double sx = 0, sy = 0, n = 0;
    int x0 = mask.cols, y0 = mask.rows, x1 = -1, y1 = -1;
    for (int y = 0; y < mask.rows; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            if (!mask.at<std::uint8_t>(y, x)) continue;
            sx += x, sy += y, n += 1;
            x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
    }
    t.present = n > 0;
    if (!t.present) return t;
    t.cx = (sx / n + 0.5) / mask.cols;
    t.cy = (sy / n + 0.5) / mask.rows;
    t.area = n / (mask.cols * mask.rows);
    t.bx = static_cast<double>(x0) / mask.cols;
    t.by = static_cast<double>(y0) / mask.rows;
    t.bw = static_cast<double>(x1 - x0 + 1) / mask.cols;
    t.bh = static_cast<double>(y1 - y0 + 1) / mask.rows;
    return t;
}

// Pixels of a blurred outline: between a quarter and three quarters of the way from the
// target's grey to the board's.
int soft_edge_pixels(const cv::Mat& bgr, double target, double board) {
    int n = 0;
    for (int y = 0; y < bgr.rows; ++y) {
        for (int x = 0; x < bgr.cols; ++x) {
            const cv::Vec3b& p = bgr.at<cv::Vec3b>(y, x);
            const double u = ((p[0] + p[1] + p[2]) / 3.0 - target) / (board - target);
            n += u > 0.25 && u < 0.75 ? 1 : 0;
        }
    }
    return n;
}

TEST(SceneRenderer, TruthIsMeasuredOnTheMask) {
    for (const char* name : {"ideal", "nonconvex", "realworld", "fast", "push"}) {
        const Renderer r(preset(name));
        for (int i = 0; i < r.frame_count(); i += 7) {
            const RenderedFrame f = r.render(i);
            ASSERT_EQ(f.bgr.type(), CV_8UC3);
            ASSERT_EQ(f.mask.type(), CV_8U);
            ASSERT_EQ(f.bgr.size(), cv::Size(r.spec().width, r.spec().height));
            ASSERT_EQ(f.mask.size(), f.bgr.size());
            const Truth want = recount(f.mask);
            SCOPED_TRACE(std::string(name) + " frame " + std::to_string(i));
            EXPECT_EQ(f.truth.frame, i);
            EXPECT_DOUBLE_EQ(f.truth.t, r.frame_time(i));
            ASSERT_EQ(f.truth.present, want.present);
            if (!want.present) continue;
            EXPECT_NEAR(f.truth.cx, want.cx, 1e-12);
            EXPECT_NEAR(f.truth.cy, want.cy, 1e-12);
            EXPECT_NEAR(f.truth.area, want.area, 1e-15);
            EXPECT_NEAR(f.truth.bx, want.bx, 1e-15);
            EXPECT_NEAR(f.truth.by, want.by, 1e-15);
            EXPECT_NEAR(f.truth.bw, want.bw, 1e-15);
            EXPECT_NEAR(f.truth.bh, want.bh, 1e-15);
            EXPECT_GT(f.truth.depth, 0.1);
            EXPECT_EQ(cv::countNonZero((f.mask != 0) & (f.mask != 255)), 0) << "mask is 0/255";
        }
    }
}

TEST(SceneRenderer, SameSpecAndSeedGiveTheSamePixels) {
    const Renderer a(preset("realworld"));
    const Renderer b(preset("realworld"));
    const RenderedFrame later = a.render(120);
    const RenderedFrame earlier = a.render(100);
    for (const int i : {100, 120}) {
        const RenderedFrame other = b.render(i);
        const RenderedFrame& mine = i == 100 ? earlier : later;
        EXPECT_EQ(cv::norm(mine.bgr, other.bgr, cv::NORM_INF), 0) << "frame " << i;
        EXPECT_EQ(cv::norm(mine.mask, other.mask, cv::NORM_INF), 0) << "frame " << i;
        EXPECT_EQ(truth_json(mine.truth), truth_json(other.truth));
    }
    SceneSpec reseeded = preset("realworld");
    reseeded.seed = 2;
    EXPECT_GT(cv::norm(Renderer(reseeded).render(100).bgr, later.bgr, cv::NORM_L1), 0);
}

TEST(SceneRenderer, TargetIsAbsentBeforeItEnters) {
    for (const char* name : {"ideal", "realworld", "exposure"}) {
        const Renderer r(preset(name));
        int first_present = -1;
        for (int i = 0; i < r.frame_count() && first_present < 0; ++i) {
            const RenderedFrame f = r.render(i);
            if (r.frame_time(i) < r.spec().empty_seconds) {
                EXPECT_FALSE(f.truth.present) << name << " frame " << i;
                EXPECT_EQ(cv::countNonZero(f.mask), 0) << name << " frame " << i;
            } else if (f.truth.present) {
                first_present = i;
                EXPECT_GT(f.truth.cx, 0.9) << name << ": comes in from the right edge";
            }
        }
        ASSERT_GE(first_present, 0) << name;
        EXPECT_LT(r.frame_time(first_present), r.spec().empty_seconds + 0.3) << name;
    }
}

TEST(SceneRenderer, BrightnessJumpsScaleTheMeanBrightness) {
    SceneSpec s;
    s.empty_seconds = 10;  // no target, just the board
    s.seconds = 3;
    s.brightness_jumps = {1.0, 2.0};
    s.brightness_jump = 0.25;
    const Renderer r(s);
    const cv::Rect all(0, 0, s.width, s.height);
    const double before = mean_grey(r.render(15).bgr, all);
    const double during = mean_grey(r.render(45).bgr, all);
    const double after = mean_grey(r.render(75).bgr, all);
    EXPECT_NEAR(before / during, 1.25, 0.01);
    EXPECT_NEAR(after / before, 1.0, 0.005);
    EXPECT_NEAR(mean_grey(r.render(29).bgr, all), before, 0.5) << "sudden, not gradual";
}

TEST(SceneRenderer, FpsSetsFrameCountAndTimes) {
    SceneSpec s;
    s.seconds = 2;
    for (const double fps : {10.0, 30.0, 60.0}) {
        s.fps = fps;
        const Renderer r(s);
        EXPECT_EQ(r.frame_count(), static_cast<int>(std::lround(2 * fps)));
        EXPECT_DOUBLE_EQ(r.frame_time(7), 7 / fps);
        EXPECT_DOUBLE_EQ(r.render(7).truth.t, 7 / fps);
    }
}

TEST(SceneRenderer, MotionBlurSoftensAMovingTargetsEdges) {
    SceneSpec moving = still(Target::sphere, 0.6, 0.3);
    moving.path.push_back({1.0, 0.7, 0.5, 0.6});  // 256 px/s across the frame
    moving.blur = 1.0;
    SceneSpec resting = still(Target::sphere, 0.6, 0.5);
    resting.blur = 1.0;
    const RenderedFrame a = Renderer(moving).render(15);
    const RenderedFrame b = Renderer(resting).render(15);
    ASSERT_TRUE(a.truth.moving);
    ASSERT_FALSE(b.truth.moving);
    const int blurred = soft_edge_pixels(a.bgr, 40, 215);
    const int sharp = soft_edge_pixels(b.bgr, 40, 215);
    EXPECT_GT(blurred, 3 * sharp) << "blurred " << blurred << " sharp " << sharp;
    EXPECT_NEAR(a.truth.area, b.truth.area, 0.01 * b.truth.area) << "mask is not blurred";
}

TEST(SceneRenderer, JpegChangesPixelsButNotTruth) {
    SceneSpec clean = preset("jpeg");
    clean.jpeg_quality = 0;
    const RenderedFrame a = Renderer(clean).render(100);
    const RenderedFrame b = Renderer(preset("jpeg")).render(100);
    EXPECT_GT(cv::norm(a.bgr, b.bgr, cv::NORM_L1) / static_cast<double>(a.bgr.total()), 1.0);
    EXPECT_EQ(cv::norm(a.mask, b.mask, cv::NORM_INF), 0);
    EXPECT_EQ(truth_json(a.truth), truth_json(b.truth));
}

TEST(SceneRenderer, AreaGrowsAsDepthShrinks) {
    for (const Target target : {Target::sphere, Target::hand}) {
        const Truth near = Renderer(still(target, 0.5)).render(0).truth;
        const Truth far = Renderer(still(target, 1.0)).render(0).truth;
        ASSERT_TRUE(near.present && far.present);
        EXPECT_NEAR(near.area / far.area, 4.0, 0.04);
        EXPECT_DOUBLE_EQ(near.depth, 0.5);
    }
    // The pinhole: a 0.10 m sphere at 0.6 m is 20% of the frame's height across.
    const Truth t = Renderer(still(Target::sphere, 0.6)).render(0).truth;
    EXPECT_NEAR(t.bh, 0.20, 2.0 / 480);
    EXPECT_NEAR(t.area, M_PI / 4 * 96 * 96 / (640 * 480), 0.003);
}

TEST(SceneRenderer, HandIsNonConvex) {
    const RenderedFrame f = Renderer(still(Target::hand, 0.4)).render(0);
    std::vector<cv::Point> pixels;
    cv::findNonZero(f.mask, pixels);
    std::vector<cv::Point> hull;
    cv::convexHull(pixels, hull);
    const double solidity =
        f.truth.area * static_cast<double>(f.mask.total()) / cv::contourArea(hull);
    EXPECT_LT(solidity, 0.75);
    EXPECT_GT(solidity, 0.4);
}

// Solidity (area over the convex hull's) and truth of a still hand with its fingers at `spread`.
std::pair<double, Truth> hand_with(double spread) {
    SceneSpec s = still(Target::hand, 0.4);
    s.path[0].spread = spread;
    const RenderedFrame f = Renderer(s).render(0);
    std::vector<cv::Point> pixels;
    cv::findNonZero(f.mask, pixels);
    std::vector<cv::Point> hull;
    cv::convexHull(pixels, hull);
    return {f.truth.area * static_cast<double>(f.mask.total()) / cv::contourArea(hull), f.truth};
}

TEST(SceneRenderer, AHandsFingersCloseSideBySideAndCurlIntoAFist) {
    const auto [fanned_solidity, fanned] = hand_with(1.0);
    const auto [together_solidity, together] = hand_with(0.0);
    const auto [fist_solidity, fist] = hand_with(-1.0);
    // Side by side the fingers overlap: a little less area, a much fuller outline.
    EXPECT_LT(together.area, 0.95 * fanned.area);
    EXPECT_GT(together.area, 0.8 * fanned.area);
    EXPECT_GT(together_solidity, fanned_solidity + 0.1);
    // A fist: the knuckles and the palm, about half the open hand, nearly convex, lower.
    EXPECT_LT(fist.area, 0.65 * fanned.area);
    EXPECT_GT(fist.area, 0.4 * fanned.area);
    EXPECT_GT(fist_solidity, 0.9);
    EXPECT_GT(fist.cy, fanned.cy + 0.02);
    // The same hand: the wrist stays where it was.
    EXPECT_NEAR(fist.by + fist.bh, fanned.by + fanned.bh, 2.0 / 480);
    // The default spread is the fanned hand, pixel for pixel.
    const RenderedFrame plain = Renderer(still(Target::hand, 0.4)).render(0);
    SceneSpec one = still(Target::hand, 0.4);
    one.path.push_back({0.5, 0.5, 0.5, 0.4, 0.0, 1.0});
    one.path.push_back({1.0, 0.5, 0.5, 0.4, 0.0, 0.0});
    const RenderedFrame at_one = Renderer(one).render(0);
    EXPECT_EQ(cv::norm(plain.bgr, at_one.bgr, cv::NORM_INF), 0.0);
}

// What an edge tracker at 160x120 sees: the strongest per-channel Sobel response.
cv::Mat edges_160x120(const cv::Mat& bgr, double threshold) {
    cv::Mat small;
    cv::resize(bgr, small, {160, 120}, 0, 0, cv::INTER_AREA);
    cv::Mat gx, gy;
    cv::Sobel(small, gx, CV_32F, 1, 0);
    cv::Sobel(small, gy, CV_32F, 0, 1);
    cv::Mat magnitude = cv::abs(gx) + cv::abs(gy);
    std::vector<cv::Mat> channels;
    cv::split(magnitude, channels);
    cv::Mat strongest = cv::max(cv::max(channels[0], channels[1]), channels[2]);
    return strongest > threshold;
}

TEST(SceneRenderer, PlainScenesShowAClosedOutlineAt160x120) {
    for (const char* name : {"ideal", "nonconvex", "exposure", "push"}) {
        const Renderer r(preset(name));
        int checked = 0, closed = 0;
        for (int i = 0; i < r.frame_count(); i += 4) {
            const RenderedFrame f = r.render(i);
            const Truth& t = f.truth;
            if (!t.present || t.bx < 0.03 || t.by < 0.03 || t.bx + t.bw > 0.97 ||
                t.by + t.bh > 0.97) {
                continue;
            }
            // Flood the non-edge pixels from a corner: a closed outline keeps the flood out of
            // the target's core.
            cv::Mat open = edges_160x120(f.bgr, 150) == 0;
            cv::floodFill(open, cv::Point(0, 0), 128);
            cv::Mat core;
            cv::resize(f.mask, core, {160, 120}, 0, 0, cv::INTER_AREA);
            cv::erode(core == 255, core, cv::Mat(), {-1, -1}, 2);
            const int leaked = cv::countNonZero((open == 128) & core);
            ++checked;
            closed += leaked == 0 ? 1 : 0;
        }
        EXPECT_GT(checked, 10) << name;
        EXPECT_GE(closed, checked * 95 / 100) << name << ": " << closed << " of " << checked;
    }
}

TEST(SceneRenderer, PresetsKeepTheTargetInViewAndSized) {
    for (const std::string_view name : preset_names()) {
        const Renderer r(preset(name));
        const double px_x = 1.0 / r.spec().width;
        const double px_y = 1.0 / r.spec().height;
        const int step = std::max(1, static_cast<int>(r.spec().fps / 4));  // every ~0.25 s
        int frames = 0, cut = 0;
        for (int i = 0; i < r.frame_count(); i += step) {
            if (r.frame_time(i) < r.spec().empty_seconds + 0.7) continue;
            const Truth t = r.render(i).truth;
            SCOPED_TRACE(std::string(name) + " frame " + std::to_string(i));
            ASSERT_TRUE(t.present);
            EXPECT_GE(t.area, 0.03);
            EXPECT_LE(t.area, 0.25);
            ++frames;
            cut += t.bx < px_x || t.by < px_y || t.bx + t.bw > 1 - px_x || t.by + t.bh > 1 - px_y;
        }
        EXPECT_GT(frames, 5) << name;
        EXPECT_LE(cut, frames / 10) << name << ": target cut by the frame's edge";
    }
}

TEST(SceneRenderer, HoldsStopTheTargetAndPushesDipItsDepth) {
    const Renderer pause(preset("pause"));
    int moving_before = 0, moving_during = 0;
    for (int i = 0; i < pause.frame_count(); ++i) {
        const double t = pause.frame_time(i);
        if (t > 3.0 && t < 4.2) moving_before += pause.render(i).truth.moving ? 1 : 0;
        if (t > 4.5 && t < 8.0) moving_during += pause.render(i).truth.moving ? 1 : 0;
    }
    EXPECT_GT(moving_before, 30);
    EXPECT_EQ(moving_during, 0);

    const Renderer push(preset("push"));
    const double rest = push.render(static_cast<int>(4.9 * 30)).truth.depth;
    const double deepest = push.render(static_cast<int>(5.35 * 30)).truth.depth;
    EXPECT_NEAR(deepest / rest, 0.75, 0.01);
}

TEST(SceneRenderer, NoiseHasTheSetSigmaAndChangesEveryFrame) {
    SceneSpec s;
    s.empty_seconds = 10;
    s.noise_sigma = 4;
    const Renderer r(s);
    cv::Mat a, b;
    r.render(10).bgr.convertTo(a, CV_64FC3);
    r.render(11).bgr.convertTo(b, CV_64FC3);
    cv::Scalar mean, sd;
    const cv::Mat difference = a - b;
    cv::meanStdDev(difference.reshape(1), mean, sd);
    EXPECT_NEAR(sd[0], 4 * std::sqrt(2.0), 0.3);
}

TEST(SceneRenderer, RejectsBadInput) {
    EXPECT_THROW(Renderer(preset("ideal")).render(-1), std::out_of_range);
    EXPECT_THROW(Renderer(preset("ideal")).render(180), std::out_of_range);
    SceneSpec bad;
    bad.fps = 0;
    EXPECT_THROW(Renderer{bad}, std::invalid_argument);
    try {
        preset("nosuch");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("nosuch"), std::string::npos);
        EXPECT_NE(what.find("lowlight"), std::string::npos);
        EXPECT_NE(what.find("push"), std::string::npos);
    }
}

TEST(SceneRenderer, TruthJsonMatchesTheSharedFormat) {
    Truth t;
    t.frame = 75;
    t.t = 2.5;
    EXPECT_EQ(truth_json(t), R"({"frame": 75, "t": 2.5, "present": false})");
    t.present = true;
    t.cx = 0.8273441;
    t.cy = 0.5;
    t.area = 0.033405;
    t.bx = 0.7375;
    t.by = 0.383333;
    t.bw = 0.1796875;
    t.bh = 0.2375;
    t.depth = 1.102914;
    EXPECT_EQ(truth_json(t),
              R"({"frame": 75, "t": 2.5, "present": true, "moving": false, "centroid": )"
              R"([0.827344, 0.5], "area": 0.033405, "bbox": [0.7375, 0.38333, 0.17969, )"
              R"(0.2375], "depth": 1.10291})");
}

}  // namespace
