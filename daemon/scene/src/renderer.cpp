// SPDX-License-Identifier: MIT
#include "raypoint/scene/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "background.hpp"
#include "camera.hpp"
#include "measure.hpp"
#include "motion_blur.hpp"
#include "passer.hpp"
#include "person.hpp"
#include "photometry.hpp"
#include "placement.hpp"
#include "rng.hpp"
#include "sleeve.hpp"
#include "sprite.hpp"
#include "trajectory.hpp"

namespace raypoint::scene {

struct Renderer::Assets {
    Camera camera;
    std::shared_ptr<const Sprite> sprite;
    // A hand whose fingers move: its sprite at each of 2 spread_levels + 1 spreads from -1 to 1
    // (empty when every keyframe has them fanned).
    std::vector<std::shared_ptr<const Sprite>> spreads;
    Trajectory trajectory;
    cv::Mat vignette;    // CV_32F
    cv::Mat background;  // CV_32FC3, vignetted, at full light
    NoisePool noise;
    std::optional<Person> person;
    std::optional<Passer> passer;

    explicit Assets(const SceneSpec& spec)
        : camera{spec.width, spec.height},
          sprite(shared_sprite(spec.target, spec.target_colour.value_or(
                                                default_colour(spec.target, spec.background)))),
          trajectory(spec, camera, *sprite),
          vignette(make_vignette({spec.width, spec.height})),
          noise({spec.width, spec.height}, spec.noise_sigma, spec.seed) {
        const cv::Size size(spec.width, spec.height);
        const std::uint64_t seed = mix_seed(spec.seed, 1);
        switch (spec.background) {
            case Background::plain:
                background = make_plain_board(size, seed);
                break;
            case Background::cluttered:
                background = make_room(size, seed);
                break;
            case Background::skin_wall:
                background = make_skin_wall(size, seed);
                break;
            case Background::desk:
                background = make_desk(size, seed);
                break;
            case Background::photo:
                background = make_photo(size, spec.background_photo, seed);
                break;
        }
        cv::Mat vignette3;
        cv::merge(std::vector<cv::Mat>{vignette, vignette, vignette}, vignette3);
        background = background.mul(vignette3);
        if (spec.person) {
            person.emplace(
                size, spec.target_colour.value_or(default_colour(Target::hand, spec.background)),
                mix_seed(spec.seed, 11));
        }
        if (!spec.passes.empty()) passer.emplace(size, spec);
        const bool moving_fingers = spec.target == Target::hand &&
                                    std::any_of(spec.path.begin(), spec.path.end(),
                                                [](const Keyframe& k) { return k.spread != 1.0; });
        if (moving_fingers) {
            const Colour colour =
                spec.target_colour.value_or(default_colour(spec.target, spec.background));
            for (int level = -spread_levels; level <= spread_levels; ++level)
                spreads.push_back(
                    shared_sprite(spec.target, colour, static_cast<double>(level) / spread_levels));
        }
    }

    const Sprite& sprite_at(const Pose& pose) const {
        if (spreads.empty()) return *sprite;
        const long level = std::lround((std::clamp(pose.spread, -1.0, 1.0) + 1.0) * spread_levels);
        return *spreads[static_cast<std::size_t>(level)];
    }
};

namespace {

// Rolling shutter: rows read at one time. 4 rows at 480 are 0.2 ms of a 25 ms readout.
constexpr int rolling_band_rows = 4;
constexpr int sensor_band_rows = 16;

void check(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("SceneSpec: " + what);
}

void validate(const SceneSpec& s) {
    check(s.width >= 16 && s.height >= 16 && s.width <= 8192 && s.height <= 8192,
          "width and height must be 16..8192 pixels");
    check(s.fps > 0 && s.fps <= 1000, "fps must be in (0, 1000]");
    check(s.seconds >= 0 && s.seconds * s.fps < 1e6, "seconds must be >= 0 (and not huge)");
    check(s.empty_seconds >= 0, "empty_seconds must be >= 0");
    check(s.noise_sigma >= 0, "noise_sigma must be >= 0");
    check(s.blur >= 0 && s.blur <= 1, "blur must be in [0, 1] (a fraction of the frame interval)");
    check(s.jpeg_quality >= 0 && s.jpeg_quality <= 100, "jpeg_quality must be 0..100");
    check(s.brightness_jump > -1, "brightness_jump must be > -1");
    check(s.darkness > 0, "darkness must be > 0");
    check(s.flicker_depth >= 0 && s.flicker_depth < 1, "flicker_depth must be in [0, 1)");
    check(s.flicker_hz > 0 && s.readout_seconds >= 0, "flicker_hz > 0 and readout_seconds >= 0");
    check(s.exposure_drift >= 0 && s.exposure_drift < 1 && s.white_balance_drift >= 0 &&
              s.white_balance_drift < 1 && s.drift_period > 0,
          "drifts must be in [0, 1) and drift_period > 0");
    check(s.speed > 0, "speed must be > 0");
    check(s.pass_seconds > 0 && s.pass_size > 0 && s.pass_size <= 2,
          "pass_seconds must be > 0 and pass_size in (0, 2]");
    check(s.target_size_m > 0, "target_size_m must be > 0");
    check(s.push_depth >= 0 && s.push_depth < 1, "push_depth must be in [0, 1)");
    check(s.push_seconds > 0, "push_seconds must be > 0");
    for (const SceneSpec::Push& p : s.shaped_pushes)
        check(p.depth >= 0 && p.depth < 1 && p.seconds > 0 && p.hold >= 0,
              "a shaped push needs depth in [0, 1), seconds > 0 and hold >= 0");
    for (const Hold& h : s.holds)
        check(h.seconds >= 0, "a hold's seconds must be >= 0");
    for (std::size_t i = 0; i < s.path.size(); ++i) {
        check(s.path[i].depth > 0, "keyframe depths must be > 0");
        check(i == 0 || s.path[i].t > s.path[i - 1].t, "keyframe times must increase");
    }
}

// How far (pixels) any corner of the outline box travels between two poses.
double travel_px(const Placement& a, const Placement& b) {
    double most = 0;
    const auto ca = a.corners();
    const auto cb = b.corners();
    for (std::size_t i = 0; i < ca.size(); ++i)
        most = std::max(most, cv::norm(ca[i] - cb[i]));
    return most;
}

std::optional<Placement> place(const Renderer::Assets& a, const SceneSpec& spec, double when) {
    const std::optional<Pose> pose = a.trajectory.at(when);
    if (!pose) return std::nullopt;
    return Placement(a.sprite_at(*pose), a.camera, spec.target_size_m, *pose);
}

// Motion blur: sub-frames spread evenly over the exposure, which is centred on t, enough of
// them that the outline steps at most ~blur_step_px from one to the next. Sub-frames before
// the target exists have no placement but still count.
struct SubFrames {
    std::vector<Placement> placements;
    int count = 1;
};

SubFrames exposure_placements(const Renderer::Assets& a, const SceneSpec& spec, double t) {
    const double exposure = spec.blur / spec.fps;
    int count = 1;
    if (exposure > 0) {
        const auto first = place(a, spec, t - exposure / 2);
        const auto last = place(a, spec, t + exposure / 2);
        if (first && last) {
            count = sub_frame_count(travel_px(*first, *last));
        }
    }
    SubFrames subs;
    subs.count = count;
    for (int k = 0; k < count; ++k) {
        const double when = count == 1 ? t : t - exposure / 2 + exposure * (k + 0.5) / count;
        if (auto p = place(a, spec, when)) subs.placements.push_back(*p);
    }
    return subs;
}

// The rows a sensor reads at one time. A global shutter is one band, the whole frame at t; with
// SceneSpec::rolling_shutter the rows are read top to bottom over readout_seconds (row y at
// t + readout_seconds * y / height, as the flicker bands are), in bands of rolling_band_rows
// each exposed at its middle row's time, so a target moving sideways shears.
struct RowBand {
    cv::Rect rows;
    SubFrames subs;
    std::optional<Placement> mid;
};

std::vector<RowBand> row_bands(const Renderer::Assets& a, const SceneSpec& spec, double t) {
    std::vector<RowBand> bands;
    if (!spec.rolling_shutter || spec.readout_seconds <= 0) {
        bands.push_back({cv::Rect(0, 0, spec.width, spec.height), exposure_placements(a, spec, t),
                         place(a, spec, t)});
        return bands;
    }
    for (int top = 0; top < spec.height; top += rolling_band_rows) {
        const int rows = std::min(rolling_band_rows, spec.height - top);
        const double when = t + spec.readout_seconds * (top + 0.5 * rows) / spec.height;
        bands.push_back({cv::Rect(0, top, spec.width, rows), exposure_placements(a, spec, when),
                         place(a, spec, when)});
    }
    return bands;
}

// CV_32FC3 light over roi (full light, vignetted): the background with the sleeve, then the
// target, blended in by their coverage averaged over the sub-frames. One colour sample serves
// the whole exposure: shading barely moves within it.
cv::Mat composite(const Renderer::Assets& a, const SceneSpec& spec, const cv::Mat& background,
                  cv::Rect roi, const SubFrames& subs, const Placement& colour_from) {
    cv::Mat light = background(roi).clone();
    cv::Mat coverage(roi.size(), CV_32F);
    const auto blend = [&](const cv::Mat& colour) {
        for (int y = 0; y < roi.height; ++y) {
            const auto* c = coverage.ptr<float>(y);
            const auto* col = colour.ptr<cv::Vec3f>(y);
            const auto* v = a.vignette.ptr<float>(roi.y + y) + roi.x;
            auto* px = light.ptr<cv::Vec3f>(y);
            for (int x = 0; x < roi.width; ++x) {
                if (c[x] > 0) px[x] += c[x] * (col[x] * v[x] - px[x]);
            }
        }
    };
    const float weight = 1.0f / static_cast<float>(subs.count);
    if (spec.sleeve_colour && a.sprite->wrist_radius > 0) {
        const cv::Size frame(spec.width, spec.height);
        coverage.setTo(0);
        for (const Placement& p : subs.placements)
            Sleeve(p, frame).add_coverage(roi, weight, coverage);
        blend(Sleeve(colour_from, frame).colour(roi, *spec.sleeve_colour));
    }
    coverage.setTo(0);
    for (const Placement& p : subs.placements)
        p.add_coverage(roi, weight, coverage);
    blend(colour_from.colour(roi));
    return light;
}

// Flicker bands and exposure/white-balance drift on a band of rows starting at `top` (CV_32FC3).
void apply_camera_light(const SceneSpec& spec, double t, int top, cv::Mat& light) {
    if (spec.flicker_depth <= 0 && spec.exposure_drift <= 0 && spec.white_balance_drift <= 0) {
        return;
    }
    const cv::Vec3d drift = drift_gains(spec, t);
    for (int y = 0; y < light.rows; ++y) {
        const cv::Vec3d row_gain = drift * flicker_gain(spec, t, top + y, spec.height);
        auto* px = light.ptr<cv::Vec3f>(y);
        for (int x = 0; x < light.cols; ++x) {
            for (int c = 0; c < 3; ++c)
                px[x][c] = static_cast<float>(px[x][c] * row_gain[c]);
        }
    }
}

// The sensor: exposure gain on the light plus noise, rounded and clipped to 8 bits, in bands
// of rows so that no frame-sized float buffer is needed. target (over roi) may be empty.
cv::Mat expose(const Renderer::Assets& a, const SceneSpec& spec, int index,
               const cv::Mat& background, const cv::Mat& target, cv::Rect roi) {
    const double gain = exposure_gain(spec, index / spec.fps);
    const cv::Mat noise = a.noise.empty() ? cv::Mat() : a.noise.frame_noise(index);
    cv::Mat bgr(spec.height, spec.width, CV_8UC3);
    cv::Mat light;
    for (int top = 0; top < spec.height; top += sensor_band_rows) {
        const cv::Rect band(0, top, spec.width, std::min(sensor_band_rows, spec.height - top));
        background(band).copyTo(light);
        const cv::Rect overlap = band & roi;
        if (!target.empty() && !overlap.empty()) {
            cv::Mat part = light(overlap - band.tl());
            target(overlap - roi.tl()).copyTo(part);
        }
        cv::Mat out = bgr(band);
        apply_camera_light(spec, index / spec.fps, top, light);
        if (noise.empty()) {
            light.convertTo(out, CV_8UC3, gain);
        } else {
            cv::scaleAdd(light, gain, noise(band), light);
            light.convertTo(out, CV_8UC3);
        }
    }
    if (spec.jpeg_quality > 0) {
        std::vector<std::uint8_t> bytes;
        cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, spec.jpeg_quality});
        bgr = cv::imdecode(bytes, cv::IMREAD_COLOR);
    }
    return bgr;
}

}  // namespace

Renderer::Renderer(SceneSpec spec) : spec_(std::move(spec)) {
    validate(spec_);
    assets_ = std::make_shared<const Assets>(spec_);
}

int Renderer::frame_count() const {
    return static_cast<int>(std::lround(spec_.seconds * spec_.fps));
}

double Renderer::frame_time(int index) const {
    return index / spec_.fps;
}

const SceneSpec& Renderer::spec() const {
    return spec_;
}

RenderedFrame Renderer::render(int index) const {
    if (index < 0 || index >= frame_count()) {
        throw std::out_of_range("Renderer::render: frame " + std::to_string(index) + " of " +
                                std::to_string(frame_count()));
    }
    const Assets& a = *assets_;
    const cv::Rect frame_rect(0, 0, spec_.width, spec_.height);
    const double t = frame_time(index);
    const std::vector<RowBand> bands = row_bands(a, spec_, t);

    const bool sleeve = spec_.sleeve_colour && a.sprite->wrist_radius > 0;
    cv::Rect roi;
    for (const RowBand& band : bands) {
        for (const Placement& p : band.subs.placements) {
            roi |= p.bounds() & band.rows;
            if (sleeve) roi |= Sleeve(p, frame_rect.size()).bounds() & band.rows;
        }
        if (band.mid) roi |= band.mid->bounds() & band.rows;
    }
    roi &= frame_rect;
    // The person and the passing object behind the target move: this frame's background.
    cv::Mat background = a.background;
    if (a.person || a.passer) background = a.background.clone();
    if (a.person) a.person->draw(t, a.vignette, background);
    if (a.passer) a.passer->draw(t, spec_.blur / spec_.fps, a.vignette, background);

    RenderedFrame out;
    out.mask = cv::Mat::zeros(spec_.height, spec_.width, CV_8U);
    cv::Mat target;
    if (!roi.empty()) {
        target.create(roi.size(), CV_32FC3);
        for (const RowBand& band : bands) {
            const cv::Rect part = roi & band.rows;
            if (part.empty()) continue;
            if (band.subs.placements.empty()) {
                background(part).copyTo(target(part - roi.tl()));
            } else {
                composite(a, spec_, background, part, band.subs,
                          band.mid ? *band.mid : band.subs.placements.back())
                    .copyTo(target(part - roi.tl()));
            }
            if (band.mid) band.mid->mask(part).copyTo(out.mask(part));
        }
    }
    out.bgr = expose(a, spec_, index, background, target, roi);
    out.truth = measure_mask(out.mask(roi), roi.tl(), frame_rect.size());
    out.truth.frame = index;
    out.truth.t = t;
    if (!out.truth.present) return out;
    out.truth.depth = a.trajectory.at(t)->depth;
    if (const auto before = index > 0 ? place(a, spec_, frame_time(index - 1)) : std::nullopt) {
        const cv::Rect prev_roi = before->bounds() & frame_rect;
        if (!prev_roi.empty()) {
            const Truth previous =
                measure_mask(before->mask(prev_roi), prev_roi.tl(), frame_rect.size());
            out.truth.moving = has_moved(previous, out.truth);
        }
    }
    return out;
}

}  // namespace raypoint::scene
