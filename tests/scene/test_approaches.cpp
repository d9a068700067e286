// SPDX-License-Identifier: MIT
// Approaches as fast as a push: where a motion clip's path holds a push by the gesture set's
// own definition, and how the set takes those spans out of the motion that must not click.

#include <algorithm>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "raypoint/scene/approaches.hpp"
#include "raypoint/scene/gesture_set.hpp"
#include "renderer_testing.hpp"

namespace {

using namespace raypoint::scene;
using raypoint::scene::render_testing::still;

std::vector<std::pair<double, double>> target_approaches(const SceneSpec& spec) {
    return approaches(spec, 0.0, spec.seconds, target_push_depth, target_push_seconds,
                      approach_press_seconds);
}

TEST(Approaches, APushAsDeepAsTheTargetsIsOne) {
    SceneSpec s = still(Target::sphere, 0.6);
    s.seconds = 4;
    s.shaped_pushes = {{1.0, 0.25, 0.3, 0.1}};  // 25% closer over 0.3 s, held 0.1 s
    const auto spans = target_approaches(s);
    ASSERT_EQ(spans.size(), 1u);
    // From within the push's way in to 0.3 s past the frame that first shows 15% closer.
    EXPECT_GE(spans[0].first, 1.0);
    EXPECT_LT(spans[0].first, 1.3);
    EXPECT_GT(spans[0].second, 1.3 + approach_press_seconds - 0.05);
    EXPECT_LT(spans[0].second, 1.3 + 0.1 + 0.3 + approach_press_seconds);
}

TEST(Approaches, AShallowPushOrASlowLeanIsNone) {
    SceneSpec shallow = still(Target::sphere, 0.6);
    shallow.seconds = 4;
    shallow.shaped_pushes = {{1.0, 0.12, 0.3, 0.1}};
    EXPECT_TRUE(target_approaches(shallow).empty());
    // 20% closer over 2 s, evenly: 6% in any 0.6 s.
    SceneSpec lean = still(Target::sphere, 0.6);
    lean.seconds = 4;
    lean.path = {{0, 0.5, 0.5, 0.6}, {1, 0.5, 0.5, 0.6}, {3, 0.5, 0.5, 0.48}, {4, 0.5, 0.5, 0.48}};
    EXPECT_TRUE(target_approaches(lean).empty());
}

TEST(Approaches, MovingAwayIsNone) {
    SceneSpec s = still(Target::sphere, 0.45);
    s.seconds = 3;
    s.path = {{0, 0.5, 0.5, 0.45}, {1, 0.5, 0.5, 0.45}, {1.4, 0.5, 0.5, 0.7}, {3, 0.5, 0.5, 0.7}};
    EXPECT_TRUE(target_approaches(s).empty());
}

TEST(Approaches, SpansAreClippedToTheRangeAsked) {
    SceneSpec s = still(Target::sphere, 0.6);
    s.seconds = 4;
    s.shaped_pushes = {{1.0, 0.3, 0.3, 0.1}};
    EXPECT_TRUE(approaches(s, 2.5, 4.0, 0.15, 0.6, 0.3).empty());
    const auto spans = approaches(s, 1.2, 1.4, 0.15, 0.6, 0.3);
    ASSERT_EQ(spans.size(), 1u);
    EXPECT_GE(spans[0].first, 1.2);
    EXPECT_LE(spans[0].second, 1.4);
}

// The set's motion clips: the motion that must not click and the approaches tile the time
// from when clicks are allowed to the clip's end, without overlapping; push clips have neither.
TEST(Approaches, TheSetsMotionAndApproachesTileEachMotionClip) {
    int clips_with_approaches = 0;
    for (const GestureClip& clip : gesture_set("full", 1)) {
        if (clip.motion_spans.empty()) {
            EXPECT_TRUE(clip.approaches.empty()) << clip.spec.name;
            continue;
        }
        std::vector<std::pair<double, double>> all = clip.motion_spans;
        all.insert(all.end(), clip.approaches.begin(), clip.approaches.end());
        std::sort(all.begin(), all.end());
        for (std::size_t i = 1; i < all.size(); ++i)
            EXPECT_DOUBLE_EQ(all[i].first, all[i - 1].second) << clip.spec.name;
        EXPECT_DOUBLE_EQ(all.back().second, clip.spec.seconds) << clip.spec.name;
        clips_with_approaches += clip.approaches.empty() ? 0 : 1;
        // A lean, a swipe's arc or a turn never comes closer as fast as a push.
        if (clip.motion == "lean" || clip.motion == "swipe" || clip.motion == "turn") {
            EXPECT_TRUE(clip.approaches.empty()) << clip.spec.name;
        }
    }
    // The renderer's own path does, at times.
    EXPECT_GT(clips_with_approaches, 0);
}

}  // namespace
