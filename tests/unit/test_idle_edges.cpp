// SPDX-License-Identifier: MIT
// An idle tracker skips the edge stage (paper 4.1's Sobel image is read only by the estimators
// of 4.2, in TRACKING and RECOVERING), and that changes no result: the Tracker against a
// reference made of the same parts over a Preprocessor that computes the edges on every frame,
// on a noisy disk that is still (INITIALIZING, SEARCHING), moves (TRACKING) and vanishes
// (SEARCHING again).

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "frames.hpp"
#include "image_evidence.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/state_machine.hpp"
#include "raypoint/core/tracker.hpp"

namespace raypoint::core {
namespace {

Timestamp at(int frame) {
    return std::llround(frame * 1e6 / 30.0);
}

Settings settings() {
    Settings s;
    s.tracking.search_threshold = 19200.0;  // see test_tracker.cpp
    // The centroids compared are the state machine's: the movement's chain, which reports its
    // own point on a pick, has its test in test_movement_chain.cpp.
    s.tracking.follow_movement = 0.0;
    return s;
}

// Still at (200, 240) until frame 70, 12 px a frame to the right until frame 95, then gone:
// plain noisy background until frame 139.
constexpr int frame_count = 140;
constexpr int gone_from = 96;
cv::Mat frame_image(int frame) {
    if (frame >= gone_from) return test::noisy_disk(frame, {-1000, -1000}, 1);
    return test::noisy_disk(frame, {200 + 12 * std::max(0, frame - 70), 240}, 50);
}

// Tracker::process's parts with the edge stage on every frame.
// It keeps its own copy of the settings: ImageEvidence holds a reference to them.
struct Reference {
    explicit Reference(const Settings& s)
        : settings(s),
          preprocessor(settings.preprocess),
          estimator(make_estimator(settings.estimator)),
          machine(settings.tracking,
                  cv::Size(settings.preprocess.work_width, settings.preprocess.work_height)),
          evidence(preprocessor, *estimator, settings.tracking,
                   settings.preprocess.compensation_minima) {}

    StepResult step(const FrameView& frame) {
        EXPECT_TRUE(preprocessor.process(frame, Preprocessor::Edges::computed));
        EXPECT_TRUE(preprocessor.edges_current());
        return machine.step(frame.timestamp, evidence);
    }

    Settings settings;
    Preprocessor preprocessor;
    std::unique_ptr<Estimator> estimator;
    StateMachine machine;
    detail::ImageEvidence evidence;
};

// Working pixel centres to fractions, as tracker.cpp converts them.
cv::Point2d fraction(cv::Point2f p) {
    return {(p.x + 0.5) / 160.0, (p.y + 0.5) / 120.0};
}

TEST(IdleEdges, SearchingSkipsTheEdgeStageAndTrackingResultsAreUnchanged) {
    Tracker tracker(settings());
    Reference reference(settings());
    int idle_frames = 0;
    int estimated_frames = 0;
    int searching_after_loss = 0;
    bool lost = false;
    for (int i = 0; i < frame_count; ++i) {
        SCOPED_TRACE(::testing::Message() << "frame " << i);
        const cv::Mat image = frame_image(i);
        const FrameView view = test::bgr_view(image, at(i));
        const TrackerState before = reference.machine.state();
        const StepResult want = reference.step(view);
        const FrameResult got = tracker.process(view);

        ASSERT_EQ(got.state, want.state);
        ASSERT_EQ(got.has_target, want.has_target);
        ASSERT_EQ(got.area.has_value(), want.area_known);
        ASSERT_EQ(got.iterations, want.iterations);
        ASSERT_EQ(got.lost, want.lost);
        ASSERT_EQ(got.loss, want.loss);
        ASSERT_EQ(got.movement, reference.preprocessor.movement());
        if (want.has_target) {
            ASSERT_EQ(got.centroid, fraction(want.estimate.centroid));
            ASSERT_EQ(got.inner, fraction(want.estimate.inner));
        }
        if (want.area_known) {
            ASSERT_EQ(*got.area, want.estimate.area / (160.0 * 120.0));
        }

        // Only a step that started in TRACKING estimates; the frame a search picks a target
        // on (SEARCHING -> TRACKING inside one step) does not.
        const bool estimates = before == TrackerState::tracking;
        ASSERT_EQ(tracker.edges_computed(), estimates);
        if (estimates) {
            ++estimated_frames;
            ASSERT_EQ(
                cv::norm(tracker.images().edges, reference.preprocessor.magnitude(), cv::NORM_INF),
                0.0);
        } else {
            ++idle_frames;
        }
        lost = lost || got.lost;
        if (lost && got.state == TrackerState::searching && !estimates) ++searching_after_loss;
    }
    // 60 INITIALIZING frames, 12 SEARCHING ones (the last picks the disk), the tracked ones,
    // and SEARCHING again once the disk has gone.
    EXPECT_GE(idle_frames, 72 + 30);
    EXPECT_GE(estimated_frames, 20);
    EXPECT_TRUE(lost);
    EXPECT_GE(searching_after_loss, 30);
}

TEST(IdleEdges, ImagesComputeTheEdgesOfAnIdleFrame) {
    // What the annotator draws on a SEARCHING frame: that frame's edges, not an older one's.
    Tracker tracker(settings());
    Preprocessor eager(settings().preprocess);
    for (int i = 0; i < 3; ++i) {
        const cv::Mat image = frame_image(i == 2 ? 80 : i);  // the last one differs
        const FrameView view = test::bgr_view(image, at(i));
        ASSERT_EQ(tracker.process(view).state, TrackerState::initializing);
        ASSERT_TRUE(eager.process(view));
    }
    EXPECT_FALSE(tracker.edges_computed());
    const TrackerImages images = tracker.images();
    EXPECT_TRUE(tracker.edges_computed());
    EXPECT_EQ(cv::norm(images.edges, eager.magnitude(), cv::NORM_INF), 0.0);
    EXPECT_GT(cv::countNonZero(images.edges), 100);
}

TEST(IdleEdges, DeferredEdgesAreComputedOnceOnDemand) {
    Preprocessor deferred(PreprocessSettings{});
    Preprocessor eager(PreprocessSettings{});
    const cv::Mat first = frame_image(0);
    const cv::Mat second = frame_image(85);
    EXPECT_FALSE(deferred.edges_current());
    ASSERT_TRUE(deferred.process(test::bgr_view(first), Preprocessor::Edges::deferred));
    EXPECT_FALSE(deferred.edges_current());
    deferred.ensure_edges();
    EXPECT_TRUE(deferred.edges_current());

    ASSERT_TRUE(eager.process(test::bgr_view(first)));
    ASSERT_TRUE(deferred.process(test::bgr_view(second), Preprocessor::Edges::deferred));
    ASSERT_TRUE(eager.process(test::bgr_view(second)));
    EXPECT_TRUE(eager.edges_current());
    EXPECT_FALSE(deferred.edges_current());  // the images still hold the first frame's edges
    EXPECT_GT(cv::norm(deferred.magnitude(), eager.magnitude(), cv::NORM_INF), 0.0);
    deferred.ensure_edges();
    EXPECT_EQ(cv::norm(deferred.magnitude(), eager.magnitude(), cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(deferred.edges(), eager.edges(), cv::NORM_INF), 0.0);
    EXPECT_EQ(deferred.movement(), eager.movement());

    // A frame the core cannot read changes nothing, the edges' currency included.
    EXPECT_FALSE(deferred.process(FrameView{}, Preprocessor::Edges::deferred));
    EXPECT_TRUE(deferred.edges_current());
}

}  // namespace
}  // namespace raypoint::core
