// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "background.hpp"
#include "rng.hpp"

namespace raypoint::scene {

// A photograph as the scene behind the target: scaled to cover the frame (never stretched) and
// cropped at a place the seed chooses, so one photo gives several backgrounds.
cv::Mat make_photo(cv::Size size, const std::string& path, std::uint64_t seed) {
    if (const std::ifstream probe(path, std::ios::binary); !probe) {
        throw std::invalid_argument("SceneSpec: background_photo " + path + ": cannot open (" +
                                    std::strerror(errno) + "): give a JPEG or PNG file");
    }
    const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
    if (image.empty()) {
        throw std::invalid_argument("SceneSpec: background_photo " + path +
                                    ": not an image OpenCV reads: give a JPEG or PNG file");
    }
    // 10% larger than covering, so the crop has room to move.
    const double scale = 1.1 * std::max(static_cast<double>(size.width) / image.cols,
                                        static_cast<double>(size.height) / image.rows);
    cv::Mat scaled;
    cv::resize(image, scaled, {}, scale, scale, scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
    Rng rng(seed);
    const int x = static_cast<int>(rng.uniform(0, scaled.cols - size.width));
    const int y = static_cast<int>(rng.uniform(0, scaled.rows - size.height));
    cv::Mat photo;
    scaled(cv::Rect({x, y}, size)).convertTo(photo, CV_32FC3);
    return photo;
}

}  // namespace raypoint::scene
