// SPDX-License-Identifier: MIT
// The table itself: every setting, once. Defaults come from the structs in core/settings.hpp.

#include "key_builders.hpp"
#include "raypoint/core/estimator.hpp"

namespace raypoint::config {

using core::AreaMode;
using core::Compensation;
using core::EdgeSource;
using core::EstimatorKind;
using core::SearchWeighting;
using core::SmoothingKind;
using detail::boolean_key;
using detail::choice_key;
using detail::device_key;
using detail::integer_key;
using detail::real_key;

const std::vector<Key>& schema() {
    // Movement sums are over 160x120 pixels: 255 at every pixel is the most there can be.
    constexpr double max_movement = 255.0 * 160 * 120;
    static const std::vector<Key> keys{
        // [preprocess] paper 4.1
        integer_key(
            "preprocess", "work_width", 32, 1920,
            "working image width in pixels; the input is filtered and subsampled to it",
            [](auto& c) -> auto& { return c.core.preprocess.work_width; }),
        integer_key(
            "preprocess", "work_height", 24, 1080, "working image height in pixels",
            [](auto& c) -> auto& { return c.core.preprocess.work_height; }),
        real_key(
            "preprocess", "filter_radius", 0.0, 40.0,
            "Poisson-disk filter radius in pixels of a 640-wide input (scaled with the input)",
            [](auto& c) -> auto& { return c.core.preprocess.filter_radius; }),
        integer_key(
            "preprocess", "edge_threshold", 1, 254,
            "a working pixel is an edge when its Sobel magnitude is over this",
            [](auto& c) -> auto& { return c.core.preprocess.edge_threshold; }),
        choice_key<EdgeSource>(
            "preprocess", "edge_source",
            "Sobel on the grey image (paper) or the strongest colour channel's",
            {{EdgeSource::luma, "luma"}, {EdgeSource::max_channel, "max-channel"}},
            [](auto& c) -> auto& { return c.core.preprocess.edge_source; }),
        choice_key<EdgeSource>(
            "preprocess", "movement_source",
            "movement value from the grey difference (paper) or the largest channel difference",
            {{EdgeSource::luma, "luma"}, {EdgeSource::max_channel, "max-channel"}},
            [](auto& c) -> auto& { return c.core.preprocess.movement_source; }),
        integer_key(
            "preprocess", "compensation_minima", 1, 255,
            "distinct minima of the difference image whose largest is the brightness change",
            [](auto& c) -> auto& { return c.core.preprocess.compensation_minima; }),
        choice_key<Compensation>(
            "preprocess", "compensation",
            "light change divided out per band of rows before the offset (flicker) or not (paper)",
            {{Compensation::frame, "frame"}, {Compensation::rows, "rows"}},
            [](auto& c) -> auto& { return c.core.preprocess.compensation; }),
        // [estimator] paper 3
        choice_key<EstimatorKind>(
            "estimator", "method", "object projection feature estimator (paper 3.1-3.4)",
            {core::estimator_names.begin(), core::estimator_names.end()},
            [](auto& c) -> auto& { return c.core.estimator.kind; }),
        integer_key(
            "estimator", "rays", 3, 256, "n: rays cast from each origin",
            [](auto& c) -> auto& { return c.core.estimator.rays; }),
        integer_key(
            "estimator", "recasts", 1, 3,
            "y: levels of casting, n^y rays in the last (iterative-ny-ray and raster)",
            [](auto& c) -> auto& { return c.core.estimator.recasts; }),
        integer_key(
            "estimator", "block_size", 1, 64, "m: raster block side in working pixels",
            [](auto& c) -> auto& { return c.core.estimator.block_size; }),
        integer_key(
            "estimator", "max_iterations", 1, 100, "iterations at most per estimate",
            [](auto& c) -> auto& { return c.core.estimator.max_iterations; }),
        real_key(
            "estimator", "tolerance", 0.01, 10.0,
            "iteration stops when centroid and inner point move less (working pixels)",
            [](auto& c) -> auto& { return c.core.estimator.tolerance; }),
        choice_key<AreaMode>(
            "estimator", "area_mode",
            "raster area and centroid: whole blocks (paper) or refined to the outline",
            {{AreaMode::blocks, "blocks"}, {AreaMode::refined, "refined"}},
            [](auto& c) -> auto& { return c.core.estimator.area_mode; }),
        integer_key(
            "estimator", "edge_escape", 0, 16,
            "an inner point on an edge first moves to a non-edge pixel this close (0: off)",
            [](auto& c) -> auto& { return c.core.estimator.edge_escape; }),
        real_key(
            "estimator", "fill_limit", 1.0, 100.0,
            "refined: a fill this many times the blocks' area has leaked and is redone",
            [](auto& c) -> auto& { return c.core.estimator.fill_limit; }),
        real_key(
            "estimator", "fill_growth", 0.0, 100.0,
            "refined fill larger than this times the last frame's has leaked (0: no check)",
            [](auto& c) -> auto& { return c.core.estimator.fill_growth; }),
        real_key(
            "estimator", "extremity", 0.0, 1.0,
            "refined: a region crossing the border keeps its part beyond this share of its reach",
            [](auto& c) -> auto& { return c.core.estimator.extremity; }),
        integer_key(
            "estimator", "extremity_contact", 1, 1000,
            "refined: longest run of border pixels from which a region crosses the border",
            [](auto& c) -> auto& { return c.core.estimator.extremity_contact; }),
        integer_key(
            "estimator", "weak_edge_threshold", 0, 254,
            "refined: a leaked or too large region is estimated again on edges over this (0: "
            "never)",
            [](auto& c) -> auto& { return c.core.estimator.weak_edge_threshold; }),
        integer_key(
            "estimator", "diagonal_tolerance", 0, 765,
            "refined fill: step diagonally between pixels of colours this close (0: never)",
            [](auto& c) -> auto& { return c.core.estimator.diagonal_tolerance; }),
        // [tracking] paper 4.2
        real_key(
            "tracking", "startup_seconds", 0.0, 30.0,
            "INITIALIZING: seconds of frame time before searching starts",
            [](auto& c) -> auto& { return c.core.tracking.startup_seconds; }),
        real_key(
            "tracking", "search_threshold", 0.0, max_movement,
            "movement sum over 160x120 pixels that starts tracking (scaled to work size)",
            [](auto& c) -> auto& { return c.core.tracking.search_threshold; }),
        real_key(
            "tracking", "idle_threshold", 0.0, max_movement,
            "movement sum over 160x120 pixels below which the scene counts as still",
            [](auto& c) -> auto& { return c.core.tracking.idle_threshold; }),
        real_key(
            "tracking", "idle_seconds", 0.0, 600.0,
            "seconds of stillness after which the target is dropped (or colour-checked)",
            [](auto& c) -> auto& { return c.core.tracking.idle_seconds; }),
        boolean_key(
            "tracking", "keep_still_target",
            "keep a still target while it keeps the colour it had when it last moved",
            [](auto& c) -> auto& { return c.core.tracking.keep_still_target; }),
        real_key(
            "tracking", "min_area", 0.0, 1.0, "smallest target area, fraction of the frame",
            [](auto& c) -> auto& { return c.core.tracking.min_area; }),
        real_key(
            "tracking", "max_area", 0.0, 1.0, "largest target area, fraction of the frame",
            [](auto& c) -> auto& { return c.core.tracking.max_area; }),
        choice_key<SearchWeighting>(
            "tracking", "search_weighting",
            "centre of mass of every difference pixel (paper) or of the strong ones only",
            {{SearchWeighting::all, "all"}, {SearchWeighting::strong, "strong"}},
            [](auto& c) -> auto& { return c.core.tracking.search_weighting; }),
        real_key(
            "tracking", "strong_fraction", 0.0, 1.0,
            "strong weighting: pixels at or above this share of the largest difference",
            [](auto& c) -> auto& { return c.core.tracking.strong_fraction; }),
        integer_key(
            "tracking", "color_patch", 1, 15, "side of the colour-match square in working pixels",
            [](auto& c) -> auto& { return c.core.tracking.color_patch; }),
        integer_key(
            "tracking", "color_tolerance", 0, 765,
            "colours match when the sum of channel differences is at most this",
            [](auto& c) -> auto& { return c.core.tracking.color_tolerance; }),
        real_key(
            "tracking", "abandon_seconds", 0.0, 60.0,
            "drop a target that stays still this long while the scene moves elsewhere (0: never)",
            [](auto& c) -> auto& { return c.core.tracking.abandon_seconds; }),
        real_key(
            "tracking", "abandon_share", 0.0, 1.0,
            "a target is still when less than this share of the movement is around it",
            [](auto& c) -> auto& { return c.core.tracking.abandon_share; }),
        real_key(
            "tracking", "abandon_grace", 0.0, 60.0,
            "never drop a target as still that had its share of the movement this recently",
            [](auto& c) -> auto& { return c.core.tracking.abandon_grace; }),
        real_key(
            "tracking", "abandon_still_share", 0.0, 1.0,
            "a target with less than this share of the movement around it has none: quiet "
            "frames do not restart its time away",
            [](auto& c) -> auto& { return c.core.tracking.abandon_still_share; }),
        real_key(
            "tracking", "max_growth", 0.0, 100.0,
            "hold back an estimate whose area grows more than this factor in 1/30 s (0: never)",
            [](auto& c) -> auto& { return c.core.tracking.max_growth; }),
        real_key(
            "tracking", "growth_hold", 0.0, 10.0,
            "seconds at most that an estimate grown too fast is held back",
            [](auto& c) -> auto& { return c.core.tracking.growth_hold; }),
        integer_key(
            "tracking", "repick_difference", 0, 255,
            "a fresh pick follows the movement at this difference summed around it, in grey "
            "levels a pixel of the colour patch (0: never)",
            [](auto& c) -> auto& { return c.core.tracking.repick_difference; }),
        real_key(
            "tracking", "repick_seconds", 0.0, 10.0,
            "seconds after a pick that it may follow the movement before it is estimated",
            [](auto& c) -> auto& { return c.core.tracking.repick_seconds; }),
        real_key(
            "tracking", "extremity_motion", 0.0, 1.0,
            "a region's far end is the target when this share of the movement is around it",
            [](auto& c) -> auto& { return c.core.tracking.extremity_motion; }),
        integer_key(
            "tracking", "recovery_near", 1, 200, "near recovery offset, working pixels",
            [](auto& c) -> auto& { return c.core.tracking.recovery_near; }),
        integer_key(
            "tracking", "recovery_far", 1, 200, "far recovery offset, working pixels",
            [](auto& c) -> auto& { return c.core.tracking.recovery_far; }),
        boolean_key(
            "tracking", "recover_small",
            "a target whose estimate is under min_area tries the recovery points before it is "
            "lost (false: lost at once, as in the paper)",
            [](auto& c) -> auto& { return c.core.tracking.recover_small; }),
        choice_key<InstructionsSetting>(
            "tracking", "instructions",
            "preprocessing's vector instructions: auto (measured at start) or one for both stages",
            {{InstructionsSetting::automatic, "auto"},
             {InstructionsSetting::scalar, "scalar"},
             {InstructionsSetting::sse2, "sse2"},
             {InstructionsSetting::avx2, "avx2"}},
            [](auto& c) -> auto& { return c.instructions; }),
        // [output] paper 4.3
        choice_key<SmoothingKind>(
            "output", "smoothing", "position smoothing: exponential once a frame, or One Euro",
            {{SmoothingKind::ema, "ema"}, {SmoothingKind::one_euro, "one-euro"}},
            [](auto& c) -> auto& { return c.core.output.smoothing; }),
        real_key(
            "output", "ema_weight", 0.0, 0.999, "ema: weight of the previous position",
            [](auto& c) -> auto& { return c.core.output.ema_weight; }),
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
            "seconds of frame time the rise must stay at press_rise to press (and at "
            "release_rise to release): one odd frame neither presses nor releases",
            [](auto& c) -> auto& { return c.core.pointer.click.press_hold_seconds; }),
        real_key(
            "click", "release_drop", 0.0, 0.9,
            "the button also comes up when sqrt(area) falls this far below its largest while "
            "down (0.25 = 25%; 0 = off): a drag that changed the size still releases",
            [](auto& c) -> auto& { return c.core.pointer.click.release_drop; }),
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
            "click", "push_travel", 0.0, 10.0,
            "while a push rises, the position may move this many times the target's size; "
            "farther it is an approach while moving, not a push (0 = off)",
            [](auto& c) -> auto& { return c.core.pointer.click.push_travel; }),
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
        // [camera] the daemon's webcam (issue: capture)
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
    return keys;
}

}  // namespace raypoint::config
