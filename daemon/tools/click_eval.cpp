// SPDX-License-Identifier: MIT
#include "click_eval.hpp"

#include "click_gesture_score.hpp"
#include "click_truth.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>

#include "input_error.hpp"
#include "raypoint/core/pointer_controller.hpp"
#include "raypoint/scene/renderer.hpp"
#include "video_source.hpp"

namespace raypoint::daemon {
namespace {

// Absolute mode: the device range mapped onto a full-HD screen's width, for offsets in pixels.
constexpr double screen_px = 1920.0;

core::FrameView view_of(const cv::Mat& bgr, core::Timestamp timestamp) {
    return core::FrameView{
        bgr.data, bgr.cols, bgr.rows, static_cast<int>(bgr.step), core::PixelFormat::bgr,
        timestamp};
}

std::vector<scene::IntendedClick> sorted(std::vector<scene::IntendedClick> clicks) {
    std::sort(clicks.begin(), clicks.end(),
              [](const auto& a, const auto& b) { return a.start < b.start; });
    return clicks;
}

std::string bin(double value, const std::vector<double>& edges, const char* unit) {
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
        if (value < edges[i + 1] || i + 2 == edges.size()) {
            std::ostringstream text;
            text << edges[i] << "-" << edges[i + 1] << unit;
            return text.str();
        }
    }
    return "?";
}

}  // namespace

void GestureTally::add(const GestureTally& o) {
    count += o.count;
    found += o.found;
    as_left += o.as_left;
    latencies.insert(latencies.end(), o.latencies.begin(), o.latencies.end());
}

void Tally::add(const Tally& o) {
    left_as_other += o.left_as_other;
    false_wheel += o.false_wheel;
    right.add(o.right);
    double_click.add(o.double_click);
    scroll.add(o.scroll);
    clicks += o.clicks;
    clicks_found += o.clicks_found;
    drags += o.drags;
    drags_found += o.drags_found;
    pushes_pressed += o.pushes_pressed;
    presses += o.presses;
    matched += o.matched;
    motion_seconds += o.motion_seconds;
    false_clicks += o.false_clicks;
    approaches += o.approaches;
    approaches_pressed += o.approaches_pressed;
    latencies.insert(latencies.end(), o.latencies.begin(), o.latencies.end());
    offsets.insert(offsets.end(), o.offsets.begin(), o.offsets.end());
}

double Tally::press_recall() const {
    return gestures() == 0 ? std::nan("") : double(pushes_pressed) / gestures();
}

double Tally::precision() const {
    return presses == 0 ? std::nan("") : double(matched) / presses;
}

double Tally::false_per_minute() const {
    return motion_seconds <= 0 ? std::nan("") : false_clicks / (motion_seconds / 60.0);
}

double median(std::vector<double> values) {
    if (values.empty()) return std::nan("");
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (values.size() % 2 == 1) return *middle;
    const double upper = *middle;
    return (upper + *std::max_element(values.begin(), middle)) / 2;
}

TrackedClip track_rendered_truth(const scene::GestureClip& clip) {
    TrackedClip tracked;
    tracked.name = clip.spec.name;
    tracked.motion = clip.motion;
    tracked.conditions = clip.conditions;
    tracked.clicks = sorted(clip.clicks);
    tracked.motion_spans = clip.motion_spans;
    tracked.approaches = clip.approaches;
    tracked.aspect = double(clip.spec.width) / clip.spec.height;
    tracked.seconds = std::round(clip.spec.seconds * clip.spec.fps) / clip.spec.fps;
    return tracked;
}

TrackedClip track_rendered(const scene::GestureClip& clip, const core::Settings& settings) {
    TrackedClip tracked = track_rendered_truth(clip);
    const scene::Renderer renderer(clip.spec);
    core::Tracker tracker(settings);
    tracked.results.reserve(static_cast<std::size_t>(renderer.frame_count()));
    for (int i = 0; i < renderer.frame_count(); ++i) {
        const scene::RenderedFrame frame = renderer.render(i);
        tracked.results.push_back(
            tracker.process(view_of(frame.bgr, core::seconds_to_us(renderer.frame_time(i)))));
    }
    return tracked;
}

TrackedClip track_recorded(const std::string& video, const std::string& truth,
                           const core::Settings& settings) {
    TrackedClip tracked;
    tracked.name = video;
    tracked.motion = "recorded";
    tracked.conditions = {{"clip", "recorded"}};
    ClickTruth read = read_click_truth(truth);
    tracked.clicks = std::move(read.clicks);
    tracked.motion_spans = std::move(read.motion_spans);
    tracked.approaches = std::move(read.approaches);
    tracked.clicks = sorted(tracked.clicks);
    VideoSource source(video, 0.0);
    core::Tracker tracker(settings);
    while (const auto frame = source.next()) {
        tracked.aspect = double(frame->bgr.cols) / frame->bgr.rows;
        tracked.results.push_back(tracker.process(view_of(frame->bgr, frame->timestamp)));
        tracked.seconds = static_cast<double>(frame->timestamp) / 1e6;
    }
    if (tracked.results.empty()) throw InputError(video + ": no frame");
    return tracked;
}

namespace {

void print_trace_header(std::FILE* out, std::string_view clip) {
    std::fprintf(out,
                 "# trace %.*s: time (s), sqrt(area) (- without one), centroid x y (fractions of "
                 "the frame), the click machine's baseline and rise, the depth signal's step "
                 "(absorbed, given back, -), the click machine's position x y (frame widths), "
                 "the click state, the buttons and wheel out\n",
                 static_cast<int>(clip.size()), clip.data());
}

// One frame of --trace: what the tracker gave, what the depth signal and the click machine made
// of it, and what went out.
void trace_frame(std::FILE* out, const core::FrameResult& result,
                 const core::PointerController& pointer, const core::PointerCommand& command) {
    const double t = static_cast<double>(result.timestamp) / 1e6;
    if (result.area) {
        std::fprintf(out, "%.3f %.4f %.3f %.3f", t, std::sqrt(*result.area), result.centroid.x,
                     result.centroid.y);
    } else {
        std::fprintf(out, "%.3f - - -", t);
    }
    const core::DepthSignal& signal = pointer.depth_signal();
    const core::ClickMachine& machine = pointer.click_machine();
    const char* step = signal.absorbed() ? "absorbed" : signal.given_back() ? "given_back" : "-";
    const std::string_view state = core::to_string(machine.state());
    const cv::Point2d where = machine.where();
    std::fprintf(out, " %.4f %+.3f %s %.3f %.3f %.*s", machine.baseline(), machine.rise(), step,
                 where.x, where.y, static_cast<int>(state.size()), state.data());
    for (const core::ButtonChange& change : command.button_changes()) {
        const std::string_view button = core::to_string(change.button);
        std::fprintf(out, " %c%.*s", change.pressed ? '+' : '-', static_cast<int>(button.size()),
                     button.data());
    }
    if (command.wheel_hi_res != 0) std::fprintf(out, " wheel %d", command.wheel_hi_res);
    std::fputc('\n', out);
}

}  // namespace

void score_clip(const TrackedClip& clip, const core::PointerSettings& settings,
                const core::OutputSettings& output, Tallies& tallies, std::FILE* misses,
                std::FILE* trace, std::string_view trace_clip) {
    if (trace != nullptr && clip.name != trace_clip) trace = nullptr;
    if (trace != nullptr) print_trace_header(trace, clip.name);
    core::PointerController pointer(settings, clip.aspect, output);
    std::vector<Press> presses;
    Outputs outputs;
    std::vector<double> times;
    std::vector<cv::Point2d> cursors;  // after each frame's command
    std::vector<double> rises;         // the click machine's, for --misses
    std::vector<core::ClickState> states;
    cv::Point2d cursor;
    const double abs_scale = screen_px / std::max(1, settings.motion.absolute_max);
    for (const core::FrameResult& result : clip.results) {
        const core::PointerCommand command = pointer.update(result);
        const double t = static_cast<double>(result.timestamp) / 1e6;
        if (command.has_absolute) {
            cursor = cv::Point2d(command.abs_x * abs_scale, command.abs_y * abs_scale);
        } else {
            cursor += cv::Point2d(command.dx, command.dy);
        }
        int left_presses = 0;
        for (const core::ButtonChange& change : command.button_changes()) {
            if (change.button == core::Button::right) {
                if (change.pressed) outputs.rights.push_back(t);
                continue;
            }
            if (change.button != core::Button::left) continue;
            if (change.pressed && ++left_presses == 2) {
                // The second press of one command: the first was a whole click before it.
                presses.back().doubled = true;
                presses.back().released.reset();
            } else if (change.pressed) {
                presses.push_back(Press{t, std::nullopt, false, cursor});
            } else if (!presses.empty() && !presses.back().released) {
                presses.back().released = t;
            }
        }
        if (command.wheel_hi_res != 0) outputs.wheel.emplace_back(t, command.wheel_hi_res);
        if (pointer.click_machine().state() == core::ClickState::dragging && !presses.empty())
            presses.back().dragged = true;
        times.push_back(t);
        cursors.push_back(cursor);
        rises.push_back(pointer.click_machine().rise());
        if (trace != nullptr) trace_frame(trace, result, pointer, command);
        states.push_back(pointer.click_machine().state());
    }
    auto cursor_before = [&](double t) {
        const auto after = std::lower_bound(times.begin(), times.end(), t);
        if (after == times.begin()) return cv::Point2d();
        return cursors[static_cast<std::size_t>(after - times.begin()) - 1];
    };

    std::vector<std::string> common = {"all"};
    for (const auto& [key, value] : clip.conditions)
        common.push_back(std::string(key).append("=").append(value));
    common.push_back("motion=" + clip.motion);
    auto each = [&](const std::vector<std::string>& groups, auto&& change) {
        for (const std::string& group : groups)
            change(tallies[group]);
    };

    // For --misses: how much of a gesture was tracked, how far the rise got, the states seen.
    auto why = [&](const scene::IntendedClick& click) {
        int frames = 0;
        int tracked_frames = 0;
        double peak = 0;
        std::string seen;
        for (std::size_t i = 0; i < times.size(); ++i) {
            if (times[i] < click.start || times[i] > click.release) continue;
            ++frames;
            tracked_frames += clip.results[i].area ? 1 : 0;
            peak = std::max(peak, rises[i]);
            const std::string name(core::to_string(states[i]));
            if (seen.find(name) == std::string::npos) seen += (seen.empty() ? "" : ",") + name;
        }
        char text[160];
        std::snprintf(text, sizeof text, "%d/%d frames with a target, peak rise %.3f, states ",
                      tracked_frames, frames, peak);
        return text + seen;
    };
    std::vector<bool> used(presses.size(), false);
    std::vector<bool> by_gesture(presses.size(), false);  // a right, double or scroll's span
    for (const scene::IntendedClick& click : clip.clicks) {
        if (click.kind != scene::GestureKind::click && click.kind != scene::GestureKind::drag) {
            const GestureScore score = score_gesture(click, presses, by_gesture, outputs);
            for (std::size_t i = 0; i < presses.size(); ++i)
                used[i] = used[i] || by_gesture[i];
            if (!score.found && misses != nullptr) {
                std::fprintf(misses, "missed %s %s at %.2f s:%s %s\n", clip.name.c_str(),
                             std::string(scene::to_string(click.kind)).c_str(), click.start,
                             score.as_left ? " a left click;" : "", why(click).c_str());
            }
            each(common, [&](Tally& tally) {
                GestureTally& g = gesture_tally(tally, click.kind);
                g.count += 1;
                g.found += score.found ? 1 : 0;
                g.as_left += score.as_left ? 1 : 0;
                if (score.found && score.at) g.latencies.push_back(*score.at - click.start);
            });
            continue;
        }
        std::vector<std::string> groups = common;
        if (click.seconds > 0) {
            groups.push_back("depth " + bin(click.depth, {0.08, 0.15, 0.25, 0.4}, ""));
            groups.push_back("push " + bin(click.seconds, {0.15, 0.3, 0.6, 0.8}, " s"));
            // The pushes the targets are stated for: at least 15% closer within 0.6 s.
            if (click.depth >= scene::target_push_depth &&
                click.seconds <= scene::target_push_seconds) {
                groups.push_back("target");
                // The same pushes by what is pushed: a hand and a ball miss for different
                // reasons (a ball's shaded side against dark furniture has no edge).
                for (const auto& [key, value] : clip.conditions)
                    if (key == "target") groups.push_back("target (" + value + ")");
            }
        }
        const bool drag = click.kind == scene::GestureKind::drag;
        std::optional<std::size_t> found;
        for (std::size_t i = 0; i < presses.size() && !found; ++i) {
            if (!used[i] && presses[i].at >= click.start &&
                presses[i].at <= click.release + match_slack)
                found = i;
        }
        if (found) used[*found] = true;
        const double to = click.release + match_slack;
        const bool other = (found && presses[*found].doubled) ||
                           any_in(outputs.rights, click.start, to) ||
                           wheel_in(outputs, click.start, to).first != 0;
        if (!found && misses != nullptr) {
            std::fprintf(misses, "missed %s %s at %.2f s: depth %.2f in %.2f s; %s\n",
                         clip.name.c_str(), std::string(scene::to_string(click.kind)).c_str(),
                         click.start, click.depth, click.seconds, why(click).c_str());
        }
        each(groups, [&](Tally& tally) {
            (drag ? tally.drags : tally.clicks) += 1;
            tally.left_as_other += other ? 1 : 0;
            if (!found) return;
            const Press& press = presses[*found];
            tally.pushes_pressed += 1;
            if (drag && press.dragged) tally.drags_found += 1;
            if (!drag && !press.dragged && press.released && !other) tally.clicks_found += 1;
            tally.latencies.push_back(press.at - click.start);
            tally.offsets.push_back(cv::norm(press.cursor - cursor_before(click.start)));
        });
    }
    auto in_span = [](double t, const std::pair<double, double>& span) {
        return t >= span.first && t <= span.second;
    };
    for (const auto& span : clip.approaches) {
        const bool pressed = std::any_of(presses.begin(), presses.end(),
                                         [&](const Press& p) { return in_span(p.at, span); });
        each(common, [&](Tally& tally) {
            tally.approaches += 1;
            tally.approaches_pressed += pressed ? 1 : 0;
        });
    }
    for (std::size_t i = 0; i < presses.size(); ++i) {
        // A press answering an approach as fast as a push is not scored either way.
        if (std::any_of(clip.approaches.begin(), clip.approaches.end(),
                        [&](const auto& span) { return in_span(presses[i].at, span); })) {
            if (misses != nullptr) {
                std::fprintf(misses, "approach press %s at %.2f s\n", clip.name.c_str(),
                             presses[i].at);
            }
            continue;
        }
        const bool in_motion =
            std::any_of(clip.motion_spans.begin(), clip.motion_spans.end(),
                        [&](const auto& span) { return in_span(presses[i].at, span); });
        if (misses != nullptr && (in_motion || !used[i])) {
            std::fprintf(misses, "%s press %s at %.2f s\n", in_motion ? "false" : "unmatched",
                         clip.name.c_str(), presses[i].at);
        }
        if (by_gesture[i]) continue;  // scored with its gesture
        each(common, [&](Tally& tally) {
            if (in_motion) {
                tally.false_clicks += 1;
            } else {
                tally.presses += 1;
                tally.matched += used[i] ? 1 : 0;
            }
        });
    }
    double motion_seconds = 0;
    int false_rights = 0;
    int false_wheel = 0;
    for (const auto& span : clip.motion_spans) {
        motion_seconds += std::min(span.second, clip.seconds) - span.first;
        for (double t : outputs.rights) {
            if (t >= span.first && t <= span.second) ++false_rights;
        }
        for (const auto& [t, units] : outputs.wheel) {
            if (t >= span.first && t <= span.second) ++false_wheel;
        }
    }
    if (misses != nullptr && false_rights + false_wheel > 0) {
        std::fprintf(misses, "false %s: %d right presses, %d wheel steps\n", clip.name.c_str(),
                     false_rights, false_wheel);
    }
    each(common, [&](Tally& tally) {
        tally.false_clicks += false_rights;
        tally.false_wheel += false_wheel;
    });
    each(common, [&](Tally& tally) { tally.motion_seconds += std::max(0.0, motion_seconds); });
}

}  // namespace raypoint::daemon
