// SPDX-License-Identifier: MIT
#include "file_frame_source.hpp"

#include <thread>

#include "input_error.hpp"

namespace raypoint::daemon {

FileFrameSource::FileFrameSource(const std::string& path, bool paced)
    : video_(path, 0.0), paced_(paced) {}

Capture FileFrameSource::next(int timeout_ms) {
    if (finished_) return end_of_input_capture();
    Capture capture;
    try {
        current_ = video_.next();
    } catch (const InputError& e) {
        current_.reset();
        capture.reason = e.what();
    }
    if (!current_) {
        finished_ = true;
        // A file that cannot be read on is lost, with the reason; one that is read to its end
        // has ended.
        if (capture.reason.empty()) return end_of_input_capture();
        capture.status = CaptureStatus::lost;
        return capture;
    }
    if (paced_) {
        // Replays as the camera delivered it: frame time on the wall clock from the first frame.
        const auto now = std::chrono::steady_clock::now();
        if (!started_) started_ = now - std::chrono::microseconds(current_->timestamp);
        const auto due = *started_ + std::chrono::microseconds(current_->timestamp);
        if (due > now) {
            std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(
                due - now, std::chrono::milliseconds(std::max(timeout_ms, 0) + 1000)));
        }
        // steady_clock is CLOCK_MONOTONIC (libstdc++ on Linux), the clock of the latencies.
        capture.ready =
            std::chrono::duration_cast<std::chrono::microseconds>(due.time_since_epoch()).count();
    }
    const cv::Mat& bgr = current_->bgr;
    capture.status = CaptureStatus::frame;
    capture.frame = core::FrameView{
        bgr.data,           bgr.cols, bgr.rows, static_cast<int>(bgr.step), core::PixelFormat::bgr,
        current_->timestamp};
    return capture;
}

std::string FileFrameSource::description() const {
    return video_.path() + " (" + std::to_string(video_.size().width) + "x" +
           std::to_string(video_.size().height) + ", " + std::to_string(video_.fps()).substr(0, 5) +
           " fps, " + (paced_ ? "paced" : "unpaced") + ")";
}

}  // namespace raypoint::daemon
