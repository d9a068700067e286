// SPDX-License-Identifier: MIT
// raypoint-core-clip: the core over a rendered clip, for counting its instructions a frame
// (.ci/instruction-count runs it under callgrind). Renders a preset in memory, converts it to
// the format asked, then runs Tracker::process over every frame with one instruction set for
// both stages. Every input to the count is fixed: the clip is rendered, not decoded; OpenCV's
// own CPU dispatch is off (cv::setUseOptimized(false)), so the same frames come out on every
// x86-64 CPU; the set is forced, not measured.

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/tracker.hpp"
#include "raypoint/loop/yuyv_clip.hpp"
#include "raypoint/scene/renderer.hpp"

namespace {

using raypoint::core::InstructionSet;

constexpr const char* usage =
    "usage: raypoint-core-clip [--preset NAME] [--format bgr|yuyv] "
    "[--instructions scalar|sse2|avx2]\n"
    "Runs the core over a rendered preset (default ideal, bgr, sse2); prints the frames and\n"
    "how many gave a position.\n";

struct Options {
    std::string preset = "ideal";
    bool yuyv = false;
    InstructionSet instructions = InstructionSet::sse2;
};

InstructionSet parse_set(const std::string& text) {
    for (const InstructionSet set :
         {InstructionSet::scalar, InstructionSet::sse2, InstructionSet::avx2}) {
        if (text == raypoint::core::to_string(set)) return set;
    }
    throw std::invalid_argument("--instructions: scalar, sse2 or avx2, not \"" + text + "\"");
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const std::string value = argv[++i];
        if (flag == "--preset") {
            o.preset = value;
        } else if (flag == "--format") {
            if (value != "bgr" && value != "yuyv")
                throw std::invalid_argument("--format: bgr or yuyv, not \"" + value + "\"");
            o.yuyv = value == "yuyv";
        } else if (flag == "--instructions") {
            o.instructions = parse_set(value);
        } else {
            throw std::invalid_argument("unknown option " + flag);
        }
    }
    if (raypoint::core::clamp_instruction_set(
            o.instructions, raypoint::core::best_instruction_set()) != o.instructions) {
        throw std::invalid_argument("--instructions " +
                                    std::string(raypoint::core::to_string(o.instructions)) +
                                    ": this CPU does not run it");
    }
    return o;
}

// What the count measures (callgrind collects inside Tracker::process only).
__attribute__((noinline)) int run_core(raypoint::core::Tracker& tracker,
                                       const std::vector<raypoint::core::FrameView>& frames) {
    int positions = 0;
    for (const raypoint::core::FrameView& frame : frames)
        positions += tracker.process(frame).has_position ? 1 : 0;
    return positions;
}

int run(const Options& o) {
    const raypoint::scene::Renderer renderer(raypoint::scene::preset(o.preset));
    const auto& spec = renderer.spec();
    const int count = renderer.frame_count();
    std::vector<cv::Mat> bgr;
    raypoint::daemon::YuyvClip yuyv(cv::Size(spec.width, spec.height), spec.fps);
    std::vector<raypoint::core::FrameView> frames;
    frames.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        cv::Mat frame = renderer.render(i).bgr;
        if (o.yuyv) {
            yuyv.append(frame);
        } else {
            bgr.push_back(frame);
        }
    }
    for (int i = 0; i < count; ++i) {
        const raypoint::core::Timestamp stamp =
            raypoint::core::seconds_to_us(renderer.frame_time(i));
        frames.push_back(o.yuyv
                             ? yuyv.view(i, stamp)
                             : raypoint::core::FrameView{bgr[i].data, bgr[i].cols, bgr[i].rows,
                                                         static_cast<int>(bgr[i].step),
                                                         raypoint::core::PixelFormat::bgr, stamp});
    }
    raypoint::core::Tracker tracker(raypoint::core::Settings{},
                                    raypoint::core::StageInstructions::both(o.instructions));
    const int positions = run_core(tracker, frames);
    std::printf("%s %s %s: %d frames %dx%d, %d with a position\n", spec.name.c_str(),
                o.yuyv ? "yuyv" : "bgr", std::string(to_string(o.instructions)).c_str(), count,
                spec.width, spec.height, positions);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        cv::setUseOptimized(false);
        cv::setNumThreads(0);
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raypoint-core-clip: %s\n%s", e.what(), usage);
        return 2;
    }
}
