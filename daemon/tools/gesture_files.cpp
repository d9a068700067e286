// SPDX-License-Identifier: MIT
#include "gesture_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "input_error.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon {

std::vector<std::string> photos_in(const std::string& dir) {
    std::error_code error;
    std::vector<std::string> photos;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (extension == ".jpg" || extension == ".jpeg" || extension == ".png")
            photos.push_back(entry.path().string());
    }
    if (error) {
        throw InputError("--backgrounds " + dir + ": cannot list the folder (" + error.message() +
                         ")");
    }
    if (photos.empty()) {
        throw InputError("--backgrounds " + dir +
                         ": no photographs there (JPEG or PNG files, .jpg .jpeg .png)");
    }
    std::sort(photos.begin(), photos.end());
    return photos;
}

void write_set(const std::vector<scene::GestureClip>& set, const std::string& dir,
               const std::string& only) {
    std::filesystem::create_directories(dir);
    for (const scene::GestureClip& clip : set) {
        if (!only.empty() && clip.spec.name != only) continue;
        const scene::Renderer renderer(clip.spec);
        const std::string video = dir + "/" + clip.spec.name + ".mp4";
        cv::VideoWriter writer(video, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), clip.spec.fps,
                               cv::Size(clip.spec.width, clip.spec.height));
        if (!writer.isOpened())
            throw InputError(video + ": cannot write (OpenCV VideoWriter, mp4v)");
        for (int i = 0; i < renderer.frame_count(); ++i)
            writer.write(renderer.render(i).bgr);
        std::ofstream truth(video + ".clicks");
        truth << scene::click_truth_text(clip);
        if (!truth) throw InputError(video + ".clicks: cannot write");
    }
}

}  // namespace raypoint::daemon
