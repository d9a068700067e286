// SPDX-License-Identifier: MIT
// The table itself: every setting, once (the output's, the pointer's and the camera's in
// schema_output_table.cpp). Defaults come from the structs in core/settings.hpp.

#include "key_builders.hpp"
#include "raypoint/core/estimator.hpp"

namespace raypoint::config {

using core::AreaMode;
using core::Compensation;
using core::EdgeSource;
using core::EstimatorKind;
using core::SearchWeighting;
using detail::boolean_key;
using detail::choice_key;
using detail::device_key;
using detail::integer_key;
using detail::real_key;

const std::vector<Key>& schema() {
    // Movement sums are over 160x120 pixels: 255 at every pixel is the most there can be.
    constexpr double max_movement = 255.0 * 160 * 120;
    static const std::vector<Key> keys = [] {
        std::vector<Key> tracker{
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
                "light change divided out per band of rows before the offset (flicker) or not "
                "(paper)",
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
            integer_key(
                "estimator", "neck_radius", 0, 8,
                "refined: the region loses what lies beyond a neck narrower than 2 x this + 1 "
                "working pixels (0: never)",
                [](auto& c) -> auto& { return c.core.estimator.neck_radius; }),
            real_key(
                "estimator", "extremity", 0.0, 1.0,
                "refined: a region crossing the border keeps its part beyond this share of its "
                "reach",
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
            real_key(
                "estimator", "weak_wander", 0.0, 160.0,
                "refined: a region whose inner point moved more working pixels than this in one "
                "estimate is estimated again on the weaker edges (0: never)",
                [](auto& c) -> auto& { return c.core.estimator.weak_wander; }),
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
                "tracking", "color_patch", 1, 15,
                "side of the colour-match square in working pixels",
                [](auto& c) -> auto& { return c.core.tracking.color_patch; }),
            integer_key(
                "tracking", "color_tolerance", 0, 765,
                "colours match when the sum of channel differences is at most this",
                [](auto& c) -> auto& { return c.core.tracking.color_tolerance; }),
            real_key(
                "tracking", "abandon_seconds", 0.0, 60.0,
                "drop a target that stays still this long while the scene moves elsewhere (0: "
                "never)",
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
                "tracking", "follow_movement", 0.0, 100.0,
                "a centroid farther than this many region radii from the movement's chain, its "
                "region holding under follow_share of the movement, is reported at the chain "
                "(0: never)",
                [](auto& c) -> auto& { return c.core.tracking.follow_movement; }),
            real_key(
                "tracking", "follow_share", 0.0, 1.0,
                "a region holding at least this share of the movement keeps its centroid "
                "(follow_movement)",
                [](auto& c) -> auto& { return c.core.tracking.follow_share; }),
            real_key(
                "tracking", "follow_radius", 0.0, 1.0,
                "the largest region radius, as a share of the working width, that "
                "follow_movement and follow_share take",
                [](auto& c) -> auto& { return c.core.tracking.follow_radius; }),
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
            real_key(
                "tracking", "change_seconds", 0.0, 10.0,
                "seconds of quiet after movement before what changed since the last quiet frame is "
                "picked, when searching or tracking scenery (0: never)",
                [](auto& c) -> auto& { return c.core.tracking.change_seconds; }),
            choice_key<InstructionsSetting>(
                "tracking", "instructions",
                "preprocessing's vector instructions: auto (measured at start) or one for both "
                "stages",
                {{InstructionsSetting::automatic, "auto"},
                 {InstructionsSetting::scalar, "scalar"},
                 {InstructionsSetting::sse2, "sse2"},
                 {InstructionsSetting::avx2, "avx2"}},
                [](auto& c) -> auto& { return c.instructions; }),
        };
        std::vector<Key> output = detail::output_keys();
        tracker.insert(tracker.end(), output.begin(), output.end());
        return tracker;
    }();
    return keys;
}

}  // namespace raypoint::config
