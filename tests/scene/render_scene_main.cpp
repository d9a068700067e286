// SPDX-License-Identifier: MIT
// raypoint-render-scene: renders a preset clip into a scene folder (the dev scenes' format):
// video.mp4 (MPEG-4 part 2, 'mp4v'), truth.jsonl, scene.json and masks.npz.

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/videoio.hpp>

#include "raypoint/scene/json.hpp"
#include "raypoint/scene/renderer.hpp"
#include "tool/npz_writer.hpp"

namespace {

namespace fs = std::filesystem;
using namespace raypoint::scene;

constexpr const char* usage =
    "usage: raypoint-render-scene --preset NAME --out DIR [--seconds S] [--fps F] [--seed N]\n"
    "                             [--no-masks]\n"
    "Writes DIR/video.mp4, truth.jsonl, scene.json and masks.npz.\n";

struct Options {
    std::string preset = "ideal";
    fs::path out;
    std::optional<double> seconds;
    std::optional<double> fps;
    std::optional<std::uint32_t> seed;
    bool masks = true;
};

double parse_number(const std::string& flag, const std::string& text) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty()) {
        throw std::invalid_argument(flag + ": not a number: \"" + text + "\"");
    }
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    bool have_out = false;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            std::cout << usage << "presets:";
            for (const auto name : preset_names())
                std::cout << ' ' << name;
            std::cout << '\n';
            std::exit(0);
        }
        if (flag == "--no-masks") {
            o.masks = false;
            continue;
        }
        if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value");
        const std::string value = argv[++i];
        if (flag == "--preset") {
            o.preset = value;
        } else if (flag == "--out") {
            o.out = value;
            have_out = true;
        } else if (flag == "--seconds") {
            o.seconds = parse_number(flag, value);
        } else if (flag == "--fps") {
            o.fps = parse_number(flag, value);
        } else if (flag == "--seed") {
            const double seed = parse_number(flag, value);
            if (seed < 0 || seed > 4294967295.0 ||
                seed != static_cast<double>(static_cast<std::uint64_t>(seed))) {
                throw std::invalid_argument("--seed: must be an integer 0..4294967295");
            }
            o.seed = static_cast<std::uint32_t>(seed);
        } else {
            throw std::invalid_argument("unknown option " + flag);
        }
    }
    if (!have_out) throw std::invalid_argument("--out DIR is required");
    return o;
}

// numpy.packbits order: the first pixel in the highest bit.
void pack_bits(const cv::Mat& mask, std::vector<std::uint8_t>& out) {
    std::uint8_t byte = 0;
    int bits = 0;
    for (int y = 0; y < mask.rows; ++y) {
        const auto* row = mask.ptr<std::uint8_t>(y);
        for (int x = 0; x < mask.cols; ++x) {
            byte = static_cast<std::uint8_t>((byte << 1U) | (row[x] ? 1U : 0U));
            if (++bits == 8) {
                out.push_back(byte);
                byte = 0;
                bits = 0;
            }
        }
    }
    if (bits > 0) out.push_back(static_cast<std::uint8_t>(byte << (8 - bits)));
}

int run(const Options& o) {
    SceneSpec spec = preset(o.preset);
    if (o.seconds) spec.seconds = *o.seconds;
    if (o.fps) spec.fps = *o.fps;
    if (o.seed) spec.seed = *o.seed;
    const Renderer renderer(spec);
    const int frames = renderer.frame_count();

    fs::create_directories(o.out);
    cv::VideoWriter video((o.out / "video.mp4").string(),
                          cv::VideoWriter::fourcc('m', 'p', '4', 'v'), spec.fps,
                          cv::Size(spec.width, spec.height));
    if (!video.isOpened())
        throw std::runtime_error("cannot open a video writer for " +
                                 (o.out / "video.mp4").string());
    std::ofstream truth(o.out / "truth.jsonl");
    if (!truth) throw std::runtime_error("cannot write " + (o.out / "truth.jsonl").string());

    std::vector<std::uint8_t> masks;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        const RenderedFrame frame = renderer.render(i);
        video.write(frame.bgr);
        truth << truth_json(frame.truth) << '\n';
        if (o.masks) pack_bits(frame.mask, masks);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    video.release();
    if (!truth.flush())
        throw std::runtime_error("cannot write " + (o.out / "truth.jsonl").string());

    std::ofstream(o.out / "scene.json") << scene_json(spec, frames);
    if (o.masks) {
        const auto per_frame = static_cast<std::uint64_t>(
            (static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height) + 7) /
            8);
        std::vector<std::uint8_t> shape(16);
        const std::uint64_t dims[2] = {static_cast<std::uint64_t>(spec.height),
                                       static_cast<std::uint64_t>(spec.width)};
        for (int d = 0; d < 2; ++d) {
            for (int b = 0; b < 8; ++b)
                shape[d * 8 + b] = static_cast<std::uint8_t>(dims[d] >> (8 * b));
        }
        raypoint::scene::tool::write_npz(
            (o.out / "masks.npz").string(),
            {{"masks", "|u1", {static_cast<std::uint64_t>(frames), per_frame}, std::move(masks)},
             {"shape", "<i8", {2}, shape}});
    }
    std::printf("%s: %d frames %dx%d at %g fps in %s (%.2f ms a frame)\n", spec.name.c_str(),
                frames, spec.width, spec.height, spec.fps, o.out.c_str(),
                1000 * seconds / std::max(1, frames));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raypoint-render-scene: %s\n%s", e.what(), usage);
        return 2;
    }
}
