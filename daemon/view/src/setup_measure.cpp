// SPDX-License-Identifier: MIT
#include "raypoint/view/setup_measure.hpp"

#include <algorithm>
#include <cmath>

namespace raypoint::view {
namespace {

// A push's peak must rise this much over the baseline: above the click machine's start_rise
// default (0.05), itself 40x a still hand's noise.
constexpr double min_push_rise = 0.06;
// Peaks closer than this are one push; the rendered pushes last 0.9 s.
constexpr double push_gap_seconds = 0.6;
// The baseline: the median scale over this window, ending before the frame so that the push
// itself does not raise it.
constexpr double baseline_from = 1.5;
constexpr double baseline_to = 0.3;
// The press at this share of the measured depth: a push shallower by a third still clicks.
constexpr double press_share = 0.6;
constexpr int min_tracked_frames = 30;

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    const auto at =
        static_cast<std::size_t>(std::lround(p * static_cast<double>(values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at),
                     values.end());
    return values[at];
}

}  // namespace

void SetupMeasure::add(const core::FrameResult& result) {
    if (result.state != core::TrackerState::tracking || !result.area) return;
    samples_.push_back({static_cast<double>(result.timestamp) * 1e-6, result.centroid.x,
                        result.centroid.y, std::sqrt(*result.area)});
}

SetupFigures SetupMeasure::figures() const {
    SetupFigures f;
    f.tracked_frames = static_cast<int>(samples_.size());
    if (samples_.empty()) return f;
    std::vector<double> xs, ys, areas;
    for (const Sample& s : samples_) {
        xs.push_back(s.x);
        ys.push_back(s.y);
        areas.push_back(s.scale * s.scale);
    }
    f.hand_area = percentile(areas, 0.5);
    f.left = percentile(xs, 0.05);
    f.right = percentile(xs, 0.95);
    f.top = percentile(ys, 0.05);
    f.bottom = percentile(ys, 0.95);

    // Each frame's rise over the median of the frames before it; a push is a run of frames
    // over min_push_rise, its depth the run's peak.
    std::vector<double> window;
    double peak = 0.0;
    double last_peak_t = -1e9;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
        const Sample& s = samples_[i];
        window.clear();
        for (std::size_t j = 0; j < i; ++j) {
            const double age = s.t - samples_[j].t;
            if (age <= baseline_from && age >= baseline_to) window.push_back(samples_[j].scale);
        }
        if (window.size() < 5) continue;
        const double rise = s.scale / percentile(window, 0.5) - 1.0;
        if (rise >= min_push_rise) {
            peak = std::max(peak, rise);
        } else if (peak > 0.0) {
            if (s.t - last_peak_t >= push_gap_seconds) {
                f.push_rises.push_back(peak);
                last_peak_t = s.t;
            }
            peak = 0.0;
        }
    }
    if (!f.push_rises.empty()) f.push_depth = percentile(f.push_rises, 0.5);
    return f;
}

std::optional<SetupProposal> SetupMeasure::propose(const config::Config& start,
                                                   int screen_width) const {
    SetupProposal proposal{start, figures()};
    const SetupFigures& f = proposal.figures;
    if (f.tracked_frames < min_tracked_frames) return std::nullopt;
    core::MotionSettings& motion = proposal.config.core.pointer.motion;
    // Relative: one sweep over the measured range crosses the screen, at slow speed.
    const double range = std::max(f.right - f.left, 0.1);
    motion.gain = std::round(screen_width / range);
    // Absolute: the measured range, widened by 0.02 a side, is the whole screen; at least the
    // middle 0.1 each way, rounded to 0.01 for the INI.
    const auto hundredths = [](double v) { return std::round(v * 100.0) / 100.0; };
    motion.active_left = hundredths(std::clamp(f.left - 0.02, 0.0, 0.45));
    motion.active_right = hundredths(std::clamp(f.right + 0.02, 0.55, 1.0));
    motion.active_top = hundredths(std::clamp(f.top - 0.02, 0.0, 0.45));
    motion.active_bottom = hundredths(std::clamp(f.bottom + 0.02, 0.55, 1.0));
    if (f.push_depth > 0.0) {
        core::ClickSettings& click = proposal.config.core.pointer.click;
        // Over start_rise, which marks a push's beginning; rounded to 0.01 for the INI.
        click.press_rise = std::max(std::round(press_share * f.push_depth * 100.0) / 100.0,
                                    click.start_rise + 0.03);
        click.release_rise = std::round(click.press_rise * 50.0) / 100.0;
    }
    return proposal;
}

}  // namespace raypoint::view
