// SPDX-License-Identifier: MIT
// The movement's chain (MovementChain, TrackingSettings::follow_movement) on working frames
// (160x120): it follows a moving target from frame to frame, stays where a target stopped, and
// is not handed to a mover elsewhere.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "frames.hpp"
#include "movement_chain.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::core {
namespace {

constexpr Timestamp frame_us = 40'000;  // 25 fps

// A bright wall with dark discs at `centres` (radius 9 working pixels: a hand at arm's length).
cv::Mat scene(std::initializer_list<cv::Point2f> centres) {
    cv::Mat frame(120, 160, CV_8UC3, cv::Scalar(200, 205, 210));
    for (const cv::Point2f c : centres)
        cv::circle(frame, cv::Point(cvRound(c.x), cvRound(c.y)), 9, cv::Scalar(40, 50, 70),
                   cv::FILLED);
    return frame;
}

// Three still frames: the scene's running average learnt, frames 0-2.
void learn(detail::MovementChain& chain, const cv::Mat& frame) {
    for (int i = 0; i < 3; ++i)
        chain.update(frame, i * frame_us);
}

TEST(MovementChain, FollowsAMovingTargetFromFrameToFrame) {
    detail::MovementChain chain;
    cv::Point2f disc(30.0F, 60.0F);
    learn(chain, scene({disc}));
    EXPECT_FALSE(chain.follow(disc));  // nothing has moved yet
    for (int i = 3; i < 30; ++i) {
        disc.x += 3.0F;  // 75 working pixels a second
        chain.update(scene({disc}), i * frame_us);
        // The tracker's centroid starts it; from then on it goes from its own point.
        const auto point = chain.follow(i == 3 ? std::optional<cv::Point2f>(disc) : std::nullopt);
        ASSERT_TRUE(point) << "frame " << i;
        EXPECT_EQ(chain.led_at(), i * frame_us);
        // On the disc, at its leading half: where it arrived, not where it left.
        EXPECT_LE(std::abs(point->y - disc.y), 3.0F) << "frame " << i;
        EXPECT_GE(point->x, disc.x - 3.0F) << "frame " << i;
        EXPECT_LE(point->x, disc.x + 9.0F) << "frame " << i;
    }
    // The target stops: no movement, and the point stays where the target was last seen.
    const auto last = chain.follow(std::nullopt);
    ASSERT_TRUE(last);
    for (int i = 30; i < 40; ++i) {
        chain.update(scene({disc}), i * frame_us);
        const auto point = chain.follow(std::nullopt);
        ASSERT_TRUE(point);
        EXPECT_EQ(*point, *last);
        EXPECT_EQ(chain.led_at(), 29 * frame_us);  // the last frame it found movement on
    }
}

// Movement before the tracker has a target starts nothing: under a flickering light or a
// camera's noise it is everywhere.
TEST(MovementChain, StartsOnlyFromTheTrackersTarget) {
    detail::MovementChain chain;
    cv::Point2f disc(30.0F, 60.0F);
    learn(chain, scene({disc}));
    for (int i = 3; i < 10; ++i) {
        disc.x += 3.0F;
        chain.update(scene({disc}), i * frame_us);
        EXPECT_FALSE(chain.follow(std::nullopt)) << "frame " << i;
        EXPECT_FALSE(chain.led_at());
    }
}

TEST(MovementChain, IsNotHandedToAMoverElsewhere) {
    detail::MovementChain chain;
    const cv::Point2f resting(40.0F, 60.0F);
    cv::Point2f passer(130.0F, 30.0F);
    learn(chain, scene({resting, passer}));
    chain.restart(resting);  // the tracker's target, which the chain agreed with
    for (int i = 3; i < 20; ++i) {
        passer.y += 3.0F;
        chain.update(scene({resting, passer}), i * frame_us);
        const auto point = chain.follow(resting);
        ASSERT_TRUE(point);
        EXPECT_EQ(*point, resting) << "frame " << i;
    }
}

TEST(MovementChain, TheShareNearAPointIsTheMovementAroundIt) {
    detail::MovementChain chain;
    const cv::Point2f still(40.0F, 60.0F);
    cv::Point2f mover(110.0F, 60.0F);
    learn(chain, scene({still, mover}));
    EXPECT_DOUBLE_EQ(chain.share_near(mover, 13.0), 1.0);  // no difference: no share to lose
    mover.x += 3.0F;
    chain.update(scene({still, mover}), 3 * frame_us);
    EXPECT_GT(chain.share_near(mover, 13.0), 0.95);
    EXPECT_LT(chain.share_near(still, 13.0), 0.01);
}

// A camera's noise, faint and everywhere, is not movement a target must hold a share of.
TEST(MovementChain, TheShareLeavesOutFaintNoise) {
    detail::MovementChain chain;
    cv::Point2f mover(110.0F, 60.0F);
    cv::RNG rng(7);
    const auto noisy = [&](cv::Point2f at) {
        cv::Mat frame = scene({at});
        cv::Mat noise(frame.size(), CV_8UC3);
        rng.fill(noise, cv::RNG::UNIFORM, 0, 12);  // up to 11 grey levels, as a cheap sensor
        return cv::Mat(frame + noise);
    };
    learn(chain, noisy(mover));
    mover.x += 3.0F;
    chain.update(noisy(mover), 3 * frame_us);
    // The disc's outline moved by 160 grey levels and more over some 60 pixels; the noise of
    // 11 levels at most over 19,200 pixels sums to more than that, and does not count.
    EXPECT_GT(chain.share_near(mover, 13.0), 0.9);
}

TEST(MovementChain, StartsOverWhenTheFrameSizeChanges) {
    detail::MovementChain chain;
    cv::Point2f disc(30.0F, 60.0F);
    for (int i = 0; i < 6; ++i) {
        disc.x += 3.0F;
        chain.update(scene({disc}), i * frame_us);
        chain.follow(disc);
    }
    ASSERT_TRUE(chain.follow(std::nullopt));
    cv::Mat larger;
    cv::resize(scene({disc}), larger, cv::Size(320, 240));
    chain.update(larger, 6 * frame_us);
    EXPECT_FALSE(chain.follow(std::nullopt));
}

// The Tracker with follow_movement on against the same Tracker with it off, on a noisy disk that
// rests, moves 12 px a frame and vanishes: the chain never changes what the state machine does,
// a target that holds the movement keeps its own centroid, the pick is the chain's point, a
// followed frame keeps its region's centroid beside the chain's point, and a searching frame has
// the chain's point only while something moves.
TEST(MovementChain, TheTrackerReportsTheChainOnlyWhereTheRegionLostTheMovement) {
    Settings off;
    off.tracking.search_threshold = 19200.0;  // see test_tracker.cpp
    off.tracking.follow_movement = 0.0;
    Settings on = off;
    on.tracking.follow_movement = 1.0;
    Tracker plain(off);
    Tracker following(on);
    int tracked = 0;
    int searched_with_target = 0;
    for (int i = 0; i < 140; ++i) {
        SCOPED_TRACE(::testing::Message() << "frame " << i);
        const cv::Mat image = i >= 96
                                  ? test::noisy_disk(i, {-1000, -1000}, 1)
                                  : test::noisy_disk(i, {200 + 12 * std::max(0, i - 70), 240}, 50);
        const FrameView view = test::bgr_view(image, std::llround(i * 1e6 / 30.0));
        const FrameResult want = plain.process(view);
        const FrameResult got = following.process(view);
        ASSERT_EQ(got.state, want.state);
        ASSERT_EQ(got.area, want.area);
        EXPECT_FALSE(want.followed);
        if (!want.has_target) {
            // Searching: a target only where the chain followed movement this frame, without
            // an area; once the disk has gone, nothing moves and nothing is reported.
            if (got.has_target) {
                EXPECT_TRUE(got.followed);
                EXPECT_EQ(got.inner, got.centroid);  // the chain's point, not the origin
                ++searched_with_target;
            }
            if (i >= 98) {
                EXPECT_FALSE(got.has_target);
            }
            continue;
        }
        ASSERT_TRUE(got.has_target);
        if (!want.area) {
            // A pick: where the disk moves, the chain started there has the leading half of its
            // movement; after it has gone, nothing moves near the chain and the pick stands.
            EXPECT_EQ(got.followed, i < 96);
        } else if (i < 96) {
            ++tracked;
            EXPECT_FALSE(got.followed);  // the disk holds the movement around it
        }
        ASSERT_EQ(got.followed ? got.region_centroid : got.centroid, want.centroid);
    }
    EXPECT_GE(tracked, 20);
    EXPECT_LE(searched_with_target, 2);
}

}  // namespace
}  // namespace raypoint::core
