// SPDX-License-Identifier: MIT
#pragma once
// A one-line progress bar on stderr, only when stderr is a terminal (never in pipes or logs).

#include <chrono>

namespace raypoint::daemon {

class ProgressBar {
  public:
    explicit ProgressBar(int total_frames);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void update(int frames_done);

  private:
    void draw(int frames_done);

    bool enabled_;
    int total_;
    std::chrono::steady_clock::time_point last_draw_;
    int last_frames_ = 0;
};

}  // namespace raypoint::daemon
