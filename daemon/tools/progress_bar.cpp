// SPDX-License-Identifier: MIT
#include "progress_bar.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace raypoint::daemon {

ProgressBar::ProgressBar(int total_frames)
    : enabled_(isatty(STDERR_FILENO) == 1), total_(total_frames) {}

ProgressBar::~ProgressBar() {
    if (!enabled_) return;
    draw(last_frames_);
    std::fputc('\n', stderr);
}

void ProgressBar::update(int frames_done) {
    last_frames_ = frames_done;
    if (!enabled_) return;
    // Ten redraws a second are enough for a person and cost nothing.
    const auto now = std::chrono::steady_clock::now();
    if (now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    draw(frames_done);
}

void ProgressBar::draw(int frames_done) {
    constexpr int width = 40;
    if (total_ > 0) {
        const int filled = std::min(width, frames_done * width / total_);
        std::fprintf(stderr, "\r[%s%s] %d/%d frames", std::string(filled, '#').c_str(),
                     std::string(width - filled, '.').c_str(), frames_done, total_);
    } else {
        std::fprintf(stderr, "\r%d frames", frames_done);
    }
    std::fflush(stderr);
}

}  // namespace raypoint::daemon
