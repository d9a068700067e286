// SPDX-License-Identifier: MIT
// A photograph behind the target (Background::photo) and the gesture set in front of photographs.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "raypoint/scene/gesture_set.hpp"
#include "raypoint/scene/renderer.hpp"
#include "renderer_testing.hpp"

namespace {

using namespace raypoint::scene;
using raypoint::scene::render_testing::mean_grey;
using raypoint::scene::render_testing::still;

// A photograph written for the test: red on the left, blue on the right (BGR), 400 x 200, so the
// frame (4:3) is covered by its height and cropped from its width.
std::string halves_photo() {
    std::string path =
        (std::filesystem::temp_directory_path() / "raypoint-test-halves.png").string();
    cv::Mat image(200, 400, CV_8UC3, cv::Scalar(200, 40, 40));
    image(cv::Rect(0, 0, 200, 200)).setTo(cv::Scalar(40, 40, 200));
    EXPECT_TRUE(cv::imwrite(path, image));
    return path;
}

TEST(PhotoBackground, ThePhotographIsBehindTheTarget) {
    SceneSpec s = still(Target::sphere, 0.6);
    s.background = Background::photo;
    s.background_photo = halves_photo();
    const RenderedFrame f = Renderer(s).render(0);
    // Scaled to cover 640 x 480 with room to move the crop: the left edge is red, the right blue.
    const cv::Scalar left = cv::mean(f.bgr(cv::Rect(10, 200, 40, 80)));
    const cv::Scalar right = cv::mean(f.bgr(cv::Rect(590, 200, 40, 80)));
    EXPECT_GT(left[2], 2 * left[0]);
    EXPECT_GT(right[0], 2 * right[2]);
    // The target in front of it, the truth measured as on any background.
    EXPECT_TRUE(f.truth.present);
    EXPECT_LT(mean_grey(f.bgr, cv::Rect(310, 230, 20, 20)), 100);
}

TEST(PhotoBackground, AnUnreadablePhotographNamesItsPath) {
    SceneSpec s = still(Target::sphere, 0.6);
    s.background = Background::photo;
    s.background_photo = "/nonexistent/raypoint-no-such-photo.jpg";
    try {
        Renderer renderer(s);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/raypoint-no-such-photo.jpg"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PhotoBackground, TheGestureSetInFrontOfPhotographsKeepsItsGestures) {
    const std::vector<GestureClip> plain = gesture_set("ci", 3);
    std::vector<GestureClip> photos = plain;
    use_photos(photos, {"a.jpg", "b.jpg"}, 3);
    ASSERT_EQ(photos.size(), plain.size());
    int a = 0;
    for (std::size_t i = 0; i < photos.size(); ++i) {
        EXPECT_EQ(photos[i].spec.background, Background::photo);
        a += photos[i].spec.background_photo == "a.jpg" ? 1 : 0;
        EXPECT_EQ(photos[i].clicks.size(), plain[i].clicks.size());
        EXPECT_EQ(photos[i].spec.path.size(), plain[i].spec.path.size());
        bool photo_condition = false;
        for (const auto& [condition, value] : photos[i].conditions)
            photo_condition = photo_condition || (condition == "background" && value == "photo");
        EXPECT_TRUE(photo_condition) << photos[i].spec.name;
    }
    // Both photographs are drawn.
    EXPECT_GT(a, 0);
    EXPECT_LT(a, static_cast<int>(photos.size()));
    EXPECT_THROW(use_photos(photos, {}, 3), std::invalid_argument);
}

}  // namespace
