// SPDX-License-Identifier: MIT
// The table's second half: what the tracker's output becomes (smoothing, cursor, clicks) and the
// daemon's camera. schema_table.cpp holds the tracker's own settings and joins the two.

#include "key_builders.hpp"

namespace raypoint::config::detail {

using core::SmoothingKind;

std::vector<Key> output_keys() {
    return {
        // [output] paper 4.3
        choice_key<SmoothingKind>(
            "output", "smoothing", "position smoothing: exponential, or One Euro",
            {{SmoothingKind::ema, "ema"}, {SmoothingKind::one_euro, "one-euro"}},
            [](auto& c) -> auto& { return c.core.output.smoothing; }),
        real_key(
            "output", "ema_weight", 0.0, 0.999, "ema: weight of the previous position",
            [](auto& c) -> auto& { return c.core.output.ema_weight; }),
        real_key(
            "output", "ema_frame_rate", 0.0, 1000.0,
            "ema: ema_weight is the weight of 1/this s of frame time, or of a frame where frames "
            "come faster, so the lag in seconds is never longer than at this rate (0 = once a "
            "frame, as the paper)",
            [](auto& c) -> auto& { return c.core.output.ema_frame_rate; }),
        real_key(
            "output", "one_euro_min_cutoff", 0.001, 100.0,
            "one-euro: cutoff at rest in Hz (lower: steadier)",
            [](auto& c) -> auto& { return c.core.output.one_euro_min_cutoff; }),
        real_key(
            "output", "one_euro_beta", 0.0, 1000.0,
            "one-euro: cutoff increase with speed (higher: less lag)",
            [](auto& c) -> auto& { return c.core.output.one_euro_beta; }),
        real_key(
            "output", "one_euro_d_cutoff", 0.001, 100.0,
            "one-euro: cutoff of the speed estimate in Hz",
            [](auto& c) -> auto& { return c.core.output.one_euro_d_cutoff; }),
        // [pointer] docs/pointer.md: tracked position to cursor motion
        choice_key<core::PointerMode>(
            "pointer", "mode",
            "relative (REL_X/REL_Y, like a mouse) or absolute (the view maps onto the screen)",
            {{core::PointerMode::relative, "relative"}, {core::PointerMode::absolute, "absolute"}},
            [](auto& c) -> auto& { return c.core.pointer.motion.mode; }),
        boolean_key(
            "pointer", "mirror", "mirror the camera horizontally, so moving right moves right",
            [](auto& c) -> auto& { return c.core.pointer.motion.mirror; }),
        real_key(
            "pointer", "gain", 0.0, 100000.0,
            "relative: device pixels per frame width of hand motion at slow speed",
            [](auto& c) -> auto& { return c.core.pointer.motion.gain; }),
        real_key(
            "pointer", "dead_zone", 0.0, 10.0,
            "relative: frame widths per second taken off the hand's speed (jitter moves nothing)",
            [](auto& c) -> auto& { return c.core.pointer.motion.dead_zone; }),
        real_key(
            "pointer", "acceleration", 0.0, 100.0,
            "relative: gain x (1 + this x speed over the dead zone in frame widths per second)",
            [](auto& c) -> auto& { return c.core.pointer.motion.acceleration; }),
        integer_key(
            "pointer", "absolute_max", 1, 1000000,
            "absolute: the device range is 0 to this on both axes",
            [](auto& c) -> auto& { return c.core.pointer.motion.absolute_max; }),
        real_key(
            "pointer", "active_left", 0.0, 1.0,
            "absolute: left edge of the view's active area, fraction of the mirrored frame",
            [](auto& c) -> auto& { return c.core.pointer.motion.active_left; }),
        real_key(
            "pointer", "active_right", 0.0, 1.0,
            "absolute: right edge of the view's active area, fraction of the mirrored frame",
            [](auto& c) -> auto& { return c.core.pointer.motion.active_right; }),
        real_key(
            "pointer", "active_top", 0.0, 1.0,
            "absolute: top edge of the view's active area, fraction of the frame",
            [](auto& c) -> auto& { return c.core.pointer.motion.active_top; }),
        real_key(
            "pointer", "active_bottom", 0.0, 1.0,
            "absolute: bottom edge of the view's active area, fraction of the frame",
            [](auto& c) -> auto& { return c.core.pointer.motion.active_bottom; }),
        // [click] docs/pointer.md: a push toward the camera clicks; rises are of sqrt(area)
        choice_key<core::ClickMode>(
            "click", "mode", "click by pushing toward the camera, by dwelling still, or not at all",
            {{core::ClickMode::depth, "depth"},
             {core::ClickMode::dwell, "dwell"},
             {core::ClickMode::off, "off"}},
            [](auto& c) -> auto& { return c.core.pointer.click.mode; }),
        real_key(
            "click", "start_rise", 0.0, 5.0,
            "a push begins when sqrt(area) rises this far over its baseline (0.05 = 5%)",
            [](auto& c) -> auto& { return c.core.pointer.click.start_rise; }),
        real_key(
            "click", "press_rise", 0.0, 5.0,
            "the button goes down when the rise reaches this within push_seconds",
            [](auto& c) -> auto& { return c.core.pointer.click.press_rise; }),
        real_key(
            "click", "release_rise", 0.0, 5.0,
            "the button comes up when the rise falls to this (below press_rise: hysteresis)",
            [](auto& c) -> auto& { return c.core.pointer.click.release_rise; }),
        real_key(
            "click", "push_seconds", 0.0, 10.0,
            "seconds from the rise passing start_rise to its reaching press_rise, at most (each "
            "moment placed between its frames); slower is an approach",
            [](auto& c) -> auto& { return c.core.pointer.click.push_seconds; }),
        real_key(
            "click", "press_hold_seconds", 0.0, 1.0,
            "seconds of frame time the rise must stay at press_rise to press (at release_rise "
            "to release, under start_rise to end an approach): one odd frame does none of them",
            [](auto& c) -> auto& { return c.core.pointer.click.press_hold_seconds; }),
        real_key(
            "click", "jump_hold_seconds", 0.0, 1.0,
            "seconds of frame time a rise that jumps from under start_rise to press_rise in one "
            "frame must stay there to press, when longer than press_hold_seconds: a push from "
            "rest grows over several frames, a region taking in a passing object in one",
            [](auto& c) -> auto& { return c.core.pointer.click.jump_hold_seconds; }),
        real_key(
            "click", "release_drop", 0.0, 0.9,
            "the button also comes up when sqrt(area) falls this far below its largest while "
            "down (0.25 = 25%; 0 = off): a drag that changed the size still releases",
            [](auto& c) -> auto& { return c.core.pointer.click.release_drop; }),
        real_key(
            "click", "release_share", 0.0, 1.0,
            "the button also comes up when the rise has come back to this share of its largest "
            "since the press (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.release_share; }),
        real_key(
            "click", "release_raw_seconds", 0.0, 10.0,
            "seconds that the target's own size back where the push began releases, even where "
            "the depth signal took the pull-back out as the region changing (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.release_raw_seconds; }),
        real_key(
            "click", "glitch_step", 0.0, 5.0,
            "a one-frame change of sqrt(area) this large (relative) that comes with a "
            "centroid jump of glitch_jump is the tracker's region changing: taken out of the "
            "depth signal",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_step; }),
        real_key(
            "click", "glitch_jump", 0.0, 10.0,
            "the centroid's one-frame jump, in units of the target's size, that marks a step "
            "of glitch_step as the region changing (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_jump; }),
        real_key(
            "click", "glitch_leap", 0.0, 10.0,
            "a one-frame change of sqrt(area) this large (relative, per 1/30 s of the frame's "
            "interval) is the region changing whatever the centroid does (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_leap; }),
        real_key(
            "click", "glitch_light", 0.0, 1.0,
            "a one-frame change of sqrt(area) of glitch_step on a frame whose light changed this "
            "much (relative: a camera's gain jump) is the outline changing with the light "
            "(0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_light; }),
        real_key(
            "click", "glitch_return", 0.0, 1.0,
            "a step taken out is given back on the next frame when the centroid has come back "
            "this share of its jump (1 = exactly back): it was a push whose frame blurred",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_return; }),
        real_key(
            "click", "glitch_return_seconds", 0.0, 1.0,
            "a step taken out may be given back on any frame this long after it, not only the "
            "next, when the centroid comes back (0 = the next frame only)",
            [](auto& c) -> auto& { return c.core.pointer.click.glitch_return_seconds; }),
        real_key(
            "click", "push_travel", 0.0, 10.0,
            "while a push rises, the position may move this many times the target's size; "
            "farther it is an approach while moving, not a push (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.push_travel; }),
        real_key(
            "click", "push_region_jump", 0.0, 10.0,
            "push_travel leaves out the centroid's jumps with the size steps the depth signal "
            "took out, up to this many times the target's size of them (0 = never)",
            [](auto& c) -> auto& { return c.core.pointer.click.push_region_jump; }),
        real_key(
            "click", "travel_hold_seconds", 0.0, 1.0,
            "seconds of frame time a rise whose travel passed half of push_travel must stay at "
            "press_rise to press, when longer than press_hold_seconds: a hand opening from a "
            "fist carries its centroid, a push does not (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.travel_hold_seconds; }),
        real_key(
            "click", "push_dip", 0.0, 1.0,
            "while a push rises, sqrt(area) may fall this far (relative) under its largest "
            "since the push began; farther it is a wobble, not a push (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.push_dip; }),
        real_key(
            "click", "refractory_seconds", 0.0, 10.0,
            "seconds after a release during which no press can come",
            [](auto& c) -> auto& { return c.core.pointer.click.refractory_seconds; }),
        real_key(
            "click", "drag_seconds", 0.0, 600.0,
            "held pushed this many seconds, the press becomes a drag: x and y move again",
            [](auto& c) -> auto& { return c.core.pointer.click.drag_seconds; }),
        real_key(
            "click", "baseline_seconds", 0.0, 600.0,
            "time constant of the baseline that follows slow changes in distance",
            [](auto& c) -> auto& { return c.core.pointer.click.baseline_seconds; }),
        real_key(
            "click", "settle_seconds", 0.0, 10.0,
            "this long after the tracker's region changes, an idle baseline rises with the size "
            "(0: off)",
            [](auto& c) -> auto& { return c.core.pointer.click.settle_seconds; }),
        real_key(
            "click", "right_seconds", 0.0, 10.0,
            "a push held still this many seconds, then pulled back without moving, "
            "right-clicks (0 = off); with it on, a push's left press waits for the pull-back or "
            "a move",
            [](auto& c) -> auto& { return c.core.pointer.click.right_seconds; }),
        real_key(
            "click", "scroll_gain", 0.0, 1000.0,
            "wheel detents a frame width of vertical motion while a push is held (0 = off): "
            "a held push moving up or down scrolls, sideways it drags",
            [](auto& c) -> auto& { return c.core.pointer.click.scroll_gain; }),
        real_key(
            "click", "double_seconds", 0.0, 10.0,
            "a push beginning within this many seconds of a click's release double-clicks "
            "(0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.double_seconds; }),
        real_key(
            "click", "hold_radius", 0.0, 1.0,
            "frame widths a held push may move before it drags or scrolls (right_seconds or "
            "scroll_gain on)",
            [](auto& c) -> auto& { return c.core.pointer.click.hold_radius; }),
        real_key(
            "click", "hold_rise", 0.0, 1.0,
            "a held push whose sqrt(area) changes by less than this (relative) is still: "
            "right_seconds counts while it is",
            [](auto& c) -> auto& { return c.core.pointer.click.hold_rise; }),
        real_key(
            "click", "hold_settle_seconds", 0.0, 10.0,
            "for this many seconds after a step of the region taken out of the depth signal, "
            "a held push's hold counts from where the position is (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.hold_settle_seconds; }),
        real_key(
            "click", "hold_flicker_seconds", 0.0, 1.0,
            "a held push's size is its largest over this many seconds, so the region losing a "
            "piece for a frame or two leaves it still; back at a size it jumped from, still "
            "since it was there once it stays twice this long (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.hold_flicker_seconds; }),
        // [dwell] click.mode = dwell
        real_key(
            "dwell", "seconds", 0.0, 60.0, "the cursor held still this many seconds clicks",
            [](auto& c) -> auto& { return c.core.pointer.dwell.seconds; }),
        real_key(
            "dwell", "radius", 0.0, 1.0,
            "still means within this distance of where it stopped, in frame widths",
            [](auto& c) -> auto& { return c.core.pointer.dwell.radius; }),
        // [safety]
        real_key(
            "safety", "min_tracking_seconds", 0.0, 600.0,
            "no click until the target has been tracked this many seconds",
            [](auto& c) -> auto& { return c.core.pointer.safety.min_tracking_seconds; }),
        // [camera] the daemon's webcam
        device_key(
            "camera", "device",
            "the webcam: auto (the first that streams), /dev/videoN or /dev/v4l/by-id/...",
            [](auto& c) -> auto& { return c.camera.device; }),
        boolean_key(
            "camera", "lock_exposure",
            "lock auto exposure, gain and white balance, so brightness cannot jump",
            [](auto& c) -> auto& { return c.camera.lock_exposure; }),
        integer_key(
            "camera", "min_width", 160, 3840,
            "capture at the camera's smallest size at least min_width x min_height (else any)",
            [](auto& c) -> auto& { return c.camera.min_width; }),
        integer_key(
            "camera", "min_height", 120, 2160, "see min_width; MJPEG is decoded down to it",
            [](auto& c) -> auto& { return c.camera.min_height; }),
    };
}

}  // namespace raypoint::config::detail
