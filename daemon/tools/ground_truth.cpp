// SPDX-License-Identifier: MIT
#include "ground_truth.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>

#include "input_error.hpp"
#include "npz_reader.hpp"

namespace raypoint::daemon {
namespace {

namespace fs = std::filesystem;

// One truth.jsonl line: a flat JSON object whose values are numbers, booleans, null or arrays
// of numbers (the scene format has nothing else).
class TruthLine {
  public:
    TruthLine(std::string_view line, std::string where) : line_(line), where_(std::move(where)) {}

    bool has(std::string_view key) const {
        const auto value = find(key);
        return value && !value->starts_with("null");
    }
    double number(std::string_view key) const {
        const auto value = find(key);
        if (!value) fail(std::string(key) + " missing");
        return parse(*value, key);
    }
    bool boolean(std::string_view key) const {
        const auto value = find(key);
        return value && value->starts_with("true");
    }
    std::vector<double> numbers(std::string_view key, std::size_t count) const {
        auto value = find(key);
        if (!value || !value->starts_with("[")) fail(std::string(key) + ": expected an array");
        std::vector<double> out;
        std::string_view rest = value->substr(1);
        while (out.size() < count) {
            out.push_back(parse(rest, key));
            const auto next = rest.find_first_of(",]");
            if (next == std::string_view::npos) fail(std::string(key) + ": unterminated array");
            rest.remove_prefix(next + 1);
        }
        return out;
    }

  private:
    std::optional<std::string_view> find(std::string_view key) const {
        // Appended: on `"\"" + std::string(...)` GCC 12 at -O2 and above gives a false -Wrestrict
        // warning.
        std::string quoted(1, '"');
        quoted.append(key).push_back('"');
        auto at = line_.find(quoted);
        if (at == std::string_view::npos) return std::nullopt;
        at = line_.find(':', at + quoted.size());
        if (at == std::string_view::npos) fail(std::string(key) + ": no value");
        at = line_.find_first_not_of(' ', at + 1);
        if (at == std::string_view::npos) fail(std::string(key) + ": no value");
        return line_.substr(at);
    }
    double parse(std::string_view text, std::string_view key) const {
        const std::string copy(text.substr(0, std::min<std::size_t>(text.size(), 40)));
        const std::size_t start = copy.find_first_not_of(' ');
        char* end = nullptr;
        const double value = std::strtod(copy.c_str() + std::min(start, copy.size()), &end);
        if (end == copy.c_str() + std::min(start, copy.size())) {
            fail(std::string(key) + ": not a number");
        }
        return value;
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(where_ + ": " + what + " (expected the scene truth format)");
    }

    std::string_view line_;
    std::string where_;
};

std::vector<scene::Truth> read_truth(const fs::path& path, int max_frames) {
    std::ifstream file(path);
    if (!file) throw InputError(path.string() + ": cannot open: " + std::strerror(errno));
    std::vector<scene::Truth> truth;
    std::string text;
    for (int number = 1; std::getline(file, text); ++number) {
        if (max_frames > 0 && static_cast<int>(truth.size()) == max_frames) break;
        if (text.empty()) continue;
        const TruthLine line(text, path.string() + ":" + std::to_string(number));
        scene::Truth t;
        t.frame = static_cast<int>(line.number("frame"));
        t.t = line.number("t");
        t.present = line.boolean("present");
        if (t.present) {
            t.moving = line.boolean("moving");
            const auto centroid = line.numbers("centroid", 2);
            t.cx = centroid[0];
            t.cy = centroid[1];
            t.area = line.number("area");
            const auto box = line.numbers("bbox", 4);
            t.bx = box[0], t.by = box[1], t.bw = box[2], t.bh = box[3];
            t.depth = line.has("depth") ? line.number("depth") : 0.0;
        }
        truth.push_back(t);
    }
    if (truth.empty()) throw InputError(path.string() + ": no truth lines");
    return truth;
}

// masks.npz: "masks" (frames x packed bits, numpy.packbits order: most significant bit first)
// and "shape" [H, W].
std::vector<cv::Mat> read_masks(const fs::path& path, std::size_t frames) {
    const std::string name = path.string();
    if (!fs::exists(path)) {
        throw InputError(name + ": cannot open: " + std::strerror(ENOENT) +
                         " (a truth.jsonl needs its masks.npz)");
    }
    const auto arrays = read_npz(name);
    const auto masks = arrays.find("masks");
    const auto shape = arrays.find("shape");
    if (masks == arrays.end() || shape == arrays.end()) {
        throw InputError(name + ": expected the arrays masks and shape");
    }
    const auto size = integer_values(shape->second, name + " shape");
    const auto& packed = masks->second;
    if (size.size() != 2 || size[0] <= 0 || size[1] <= 0 || packed.shape.size() != 2 ||
        packed.dtype != "|u1" ||
        packed.shape[1] * 8 < static_cast<std::uint64_t>(size[0] * size[1])) {
        throw InputError(name + ": masks and shape do not fit together");
    }
    if (packed.shape[0] < frames) {
        throw InputError(name + ": " + std::to_string(packed.shape[0]) + " masks for " +
                         std::to_string(frames) + " truth lines");
    }
    const int height = static_cast<int>(size[0]);
    const int width = static_cast<int>(size[1]);
    std::vector<cv::Mat> out;
    out.reserve(frames);
    for (std::size_t f = 0; f < frames; ++f) {
        const std::uint8_t* bits = packed.bytes.data() + f * packed.shape[1];
        cv::Mat mask(height, width, CV_8U);
        auto* pixel = mask.ptr<std::uint8_t>();
        for (std::size_t i = 0; i < mask.total(); ++i)
            pixel[i] = ((bits[i / 8] >> (7 - i % 8)) & 1U) != 0 ? 255 : 0;
        out.push_back(mask);
    }
    return out;
}

}  // namespace

std::optional<GroundTruth> read_ground_truth(const fs::path& folder, int max_frames) {
    const fs::path truth_path = folder / "truth.jsonl";
    if (!fs::exists(truth_path)) return std::nullopt;
    GroundTruth truth;
    truth.truth = read_truth(truth_path, max_frames);
    truth.masks = read_masks(folder / "masks.npz", truth.truth.size());
    return truth;
}

}  // namespace raypoint::daemon
