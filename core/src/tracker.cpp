// SPDX-License-Identifier: MIT
#include "raypoint/core/tracker.hpp"

#include <algorithm>
#include <cmath>

#include "image_evidence.hpp"
#include "movement_chain.hpp"
#include "raypoint/core/preprocess.hpp"
#include "raypoint/core/smoothing.hpp"
#include "raypoint/core/state_machine.hpp"

namespace raypoint::core {

struct Tracker::Impl {
    Impl(const Settings& s, StageInstructions instructions)
        : settings(s),
          preprocessor(s.preprocess, instructions),
          estimator(make_estimator(s.estimator)),
          machine(s.tracking, cv::Size(s.preprocess.work_width, s.preprocess.work_height)),
          smoother(s.output),
          evidence(preprocessor, *estimator, settings.tracking, s.preprocess.compensation_minima) {}

    Settings settings;
    Preprocessor preprocessor;
    std::unique_ptr<Estimator> estimator;
    StateMachine machine;
    PositionSmoother smoother;
    detail::ImageEvidence evidence;
    detail::MovementChain chain;
    std::int64_t frames = 0;
    std::optional<double> reference_area;  // the area when tracking started (paper 4.3)
    EstimatorTrace empty_trace;
};

Tracker::Tracker(const Settings& settings, StageInstructions instructions)
    : impl_(std::make_unique<Impl>(settings, instructions)) {}
Tracker::~Tracker() = default;

void Tracker::set_instructions(StageInstructions instructions) noexcept {
    impl_->preprocessor.set_instructions(instructions);
}

StageInstructions Tracker::instructions() const noexcept {
    return impl_->preprocessor.instructions();
}

void Tracker::ensure_edges() noexcept {
    impl_->preprocessor.ensure_edges();
}

bool Tracker::edges_computed() const noexcept {
    return impl_->preprocessor.edges_current();
}

const Settings& Tracker::settings() const noexcept {
    return impl_->settings;
}

// The edge stage is deferred to the state machine's first estimate (ImageEvidence); a caller
// drawing the images gets the last frame's edges all the same, computed here if it had none.
TrackerImages Tracker::images() const noexcept {
    impl_->preprocessor.ensure_edges();
    return {impl_->preprocessor.color(), impl_->preprocessor.magnitude(),
            impl_->preprocessor.difference(), impl_->estimator->trace()};
}

FrameResult Tracker::process(const FrameView& frame) noexcept {
    Impl& d = *impl_;
    FrameResult result;
    result.frame = d.frames++;
    result.timestamp = frame.timestamp;
    if (!d.preprocessor.process(frame, Preprocessor::Edges::deferred)) {
        result.state = d.machine.state();
        return result;
    }
    const StepResult step = d.machine.step(frame.timestamp, d.evidence);
    result.state = step.state;
    result.movement = d.preprocessor.movement();
    result.light_change = d.preprocessor.light_change();
    result.iterations = step.iterations;
    result.recovered = step.recovered;
    result.held = step.held;
    result.lost = step.lost;
    result.loss = step.loss;
    // Working pixel centres are at integer coordinates; fractions are of the whole frame.
    const double width = d.settings.preprocess.work_width;
    const double height = d.settings.preprocess.work_height;
    const auto to_fraction = [&](cv::Point2f p) {
        return cv::Point2d((p.x + 0.5) / width, (p.y + 0.5) / height);
    };
    if (step.recovery_from) result.recovery_from = to_fraction(*step.recovery_from);
    if (step.acquired || !step.has_target) d.reference_area.reset();
    const bool following = d.settings.tracking.follow_movement > 0.0;
    // The chain runs on every frame, with a target or without, so it is where the movement
    // is when a target's region fails.
    cv::Point2f chained;
    bool has_chained = false;
    if (following) {
        d.chain.update(d.preprocessor.color(), frame.timestamp);
        const auto target =
            step.has_target ? std::optional<cv::Point2f>(step.estimate.centroid) : std::nullopt;
        if (const auto point = d.chain.follow(target)) {
            chained = *point;
            has_chained = true;
        }
    }
    if (!step.has_target) {
        // The region failed and the state machine searches: on a frame whose movement the
        // chain followed, the target is where that movement led, the chain's point its centroid
        // and its inner point. No area: nothing clicks.
        if (has_chained && d.chain.led_at() == frame.timestamp) {
            result.has_target = true;
            result.centroid = to_fraction(chained);
            result.inner = result.centroid;
            result.followed = true;
        }
        return result;
    }
    result.has_target = true;
    result.centroid = to_fraction(step.estimate.centroid);
    result.inner = to_fraction(step.estimate.inner);
    if (following) {
        // The region's radius in working pixels, at least 4 (a hand at the far end of a room),
        // at most follow_radius of the frame's width: a region larger than a hand near the
        // camera may have leaked into the body with the hand at its edge, and its disc would
        // hold the hand's movement and the chain's point both.
        const double largest = d.settings.tracking.follow_radius * width;
        const double radius =
            std::clamp(std::sqrt(step.estimate.area / CV_PI), 4.0, std::max(4.0, largest));
        const cv::Point2f centroid = step.estimate.centroid;
        const bool led = has_chained && d.chain.led_at() == frame.timestamp;
        if (!step.area_known) {
            // A pick, the difference's centre of mass: where the chain followed the movement
            // this frame, its point is nearer the target than the pick, and stays its own.
            if (led) {
                result.region_centroid = result.centroid;
                result.centroid = to_fraction(chained);
                result.followed = true;
            }
        } else if (!has_chained ||
                   d.chain.share_near(centroid, radius + 4.0) >= d.settings.tracking.follow_share ||
                   cv::norm(chained - centroid) <= d.settings.tracking.follow_movement * radius) {
            d.chain.restart(centroid);
        } else {
            result.region_centroid = result.centroid;
            result.centroid = to_fraction(chained);
            result.followed = true;
        }
    }
    if (!step.area_known) return result;

    const double area = step.estimate.area / (width * height);
    result.area = area;
    // z = sqrt(area) relative to the area when tracking started: 0 then, growing as the
    // target comes closer (sqrt(area) is proportional to 1/depth for a rigid target).
    const bool first = !d.reference_area.has_value();
    if (first) d.reference_area = area;
    const cv::Point3d raw(result.centroid.x, result.centroid.y,
                          std::sqrt(area) - std::sqrt(*d.reference_area));
    if (first) {
        d.smoother.reset(raw, frame.timestamp);
        result.position = raw;
    } else {
        result.position = d.smoother.update(raw, frame.timestamp);
    }
    result.has_position = true;
    return result;
}

}  // namespace raypoint::core
