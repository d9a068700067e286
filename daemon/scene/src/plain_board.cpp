// SPDX-License-Identifier: MIT
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "background.hpp"
#include "rng.hpp"

namespace raypoint::scene {

// A white board under room light: a slightly warm white, a gentle light gradient, blotchy
// unevenness a few percent deep and a faint fine texture.
cv::Mat make_plain_board(cv::Size size, std::uint64_t seed) {
    Rng rng(seed);
    const cv::Vec3f base(static_cast<float>(rng.uniform(214, 222)),
                         static_cast<float>(rng.uniform(220, 226)),
                         static_cast<float>(rng.uniform(222, 229)));

    // Unevenness: a coarse random grid, smoothly interpolated to the frame's size.
    cv::Mat coarse(5, 7, CV_32F);
    for (int j = 0; j < coarse.rows; ++j) {
        for (int i = 0; i < coarse.cols; ++i) {
            coarse.at<float>(j, i) = static_cast<float>(rng.uniform(-0.025, 0.025));
        }
    }
    cv::Mat uneven;
    cv::resize(coarse, uneven, size, 0, 0, cv::INTER_CUBIC);

    // Fine texture: blurred white noise, about one grey level.
    cv::Mat fine(size, CV_32F);
    cv::RNG cv_rng(mix_seed(seed, 1));
    cv_rng.fill(fine, cv::RNG::NORMAL, 0, 2.0);
    cv::GaussianBlur(fine, fine, cv::Size(), 1.2);

    const double angle = rng.uniform(0, 6.283185307179586);
    const double gx = std::cos(angle) * 0.04 / size.width;
    const double gy = std::sin(angle) * 0.04 / size.height;

    cv::Mat board(size, CV_32FC3);
    for (int y = 0; y < size.height; ++y) {
        const auto* u = uneven.ptr<float>(y);
        const auto* f = fine.ptr<float>(y);
        auto* out = board.ptr<cv::Vec3f>(y);
        for (int x = 0; x < size.width; ++x) {
            const auto light = static_cast<float>(1 + gx * (x - size.width / 2.0) +
                                                  gy * (y - size.height / 2.0) + u[x]);
            out[x] = base * light + cv::Vec3f(f[x], f[x], f[x]);
        }
    }
    return board;
}

}  // namespace raypoint::scene
