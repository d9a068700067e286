// SPDX-License-Identifier: MIT
#include "fault_harness.hpp"

#include <linux/input-event-codes.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "raypoint/scene/presets.hpp"
#include "raypoint/scene/renderer.hpp"

namespace raypoint::daemon::test {

ScriptedSource::ScriptedSource(const std::vector<cv::Mat>& clip, std::vector<FaultWindow> script,
                               int loops)
    : clip_(clip), script_(std::move(script)), frames_(static_cast<int>(clip.size()) * loops) {}

const FaultWindow* ScriptedSource::window_at(int index) const noexcept {
    for (const FaultWindow& window : script_) {
        if (index >= window.first && index <= window.last) return &window;
    }
    return nullptr;
}

Capture ScriptedSource::next(int /*timeout_ms*/) {
    if (lost_) return Capture{CaptureStatus::lost, {}, "VIDIOC_DQBUF: No such device", -1};
    if (index_ >= frames_) return end_of_input_capture();
    if (before_frame) before_frame(index_);
    const int index = index_++;
    const FaultWindow* window = window_at(index);
    const Fault fault = window != nullptr ? window->fault : Fault::none;
    const cv::Mat& frame = clip_[static_cast<std::size_t>(index) % clip_.size()];
    switch (fault) {
        case Fault::none:
            frame.copyTo(shown_);
            frame.copyTo(last_good_);
            break;
        case Fault::black:
            shown_ = cv::Mat::zeros(frame.size(), frame.type());
            break;
        case Fault::saturated:
            shown_ = cv::Mat(frame.size(), frame.type(), cv::Scalar::all(255));
            break;
        case Fault::frozen:
            // The same frame again and again (a driver repeating its last buffer).
            if (last_good_.empty()) frame.copyTo(last_good_);
            last_good_.copyTo(shown_);
            break;
        case Fault::flicker:
            // Every other frame dark: a fluorescent light beating with the exposure.
            if (index % 2 == 0) {
                frame.copyTo(shown_);
            } else {
                shown_ = frame * 0.25;
            }
            break;
        case Fault::capture_error:
            lost_ = true;
            index_ = window->last + 1;  // the camera misses the frames of its absence
            return Capture{CaptureStatus::lost, {}, "VIDIOC_DQBUF: No such device", -1};
    }
    Capture capture;
    capture.status = CaptureStatus::frame;
    capture.frame = core::FrameView{shown_.data,
                                    shown_.cols,
                                    shown_.rows,
                                    static_cast<int>(shown_.step[0]),
                                    core::PixelFormat::bgr,
                                    index * frame_interval_us};
    return capture;
}

bool ScriptedSource::reopen() {
    ++reopen_attempts_;
    if (!lost_) return true;
    // Away for failed_reopens attempts, as an unplugged camera whose node is not back yet.
    if (++attempts_this_loss_ <= failed_reopens) {
        error_ = "open /dev/video0: No such file or directory";
        return false;
    }
    lost_ = false;
    attempts_this_loss_ = 0;
    error_.clear();
    return true;
}

void DeviceModelSink::emit(const core::PointerCommand& command,
                           core::Timestamp timestamp) noexcept {
    write(encoder_.encode(command), timestamp);
}

void DeviceModelSink::release_all(core::Timestamp timestamp) noexcept {
    write(encoder_.release_all(), timestamp);
}

void DeviceModelSink::write(const EventBatch& batch, core::Timestamp timestamp) noexcept {
    const int error = write_batch(encoder_, batch, [&](const EvdevEvent& event) {
        if (fail_with != 0) return -fail_with;
        if (event.type == EV_KEY) {
            const auto button = button_of_code(event.code);
            bool& down = down_[static_cast<std::size_t>(*button)];
            // The input core drops a press of a pressed key and a release of a released one.
            if (down != (event.value != 0)) {
                down = event.value != 0;
                ++(down ? presses_ : releases_);
                if (record_) keys_.push_back(KeyEvent{timestamp, *button, down});
            }
        } else if (event.type == EV_REL || event.type == EV_ABS) {
            ++motion_events_;
            if (record_) motion_at_.push_back(timestamp);
        }
        return 0;
    });
    if (error != 0) {
        last_error_ = error;
        ++failed_writes_;
    }
}

long long DeviceModelSink::motion_since(core::Timestamp from) const noexcept {
    return std::count_if(motion_at_.begin(), motion_at_.end(),
                         [&](core::Timestamp at) { return at >= from; });
}

const std::vector<cv::Mat>& rendered_clip(const std::string& preset) {
    static std::map<std::string, std::vector<cv::Mat>> clips;
    auto& clip = clips[preset];
    if (clip.empty()) {
        scene::SceneSpec spec = scene::preset(preset);
        spec.width = 320;
        spec.height = 240;
        // The harness's timestamps are 30 fps ones.
        if (spec.fps != 30) throw std::invalid_argument(preset + ": not a 30 fps clip");
        const scene::Renderer renderer(spec);
        for (int i = 0; i < renderer.frame_count(); ++i)
            clip.push_back(renderer.render(i).bgr);
    }
    return clip;
}

}  // namespace raypoint::daemon::test
