// SPDX-License-Identifier: MIT
#pragma once
// Every tunable of the tracking core, as plain data. Defaults are the paper's numbers unless the
// comment says otherwise; config/src/schema_table.cpp is the one place that names, ranges and
// documents them, and docs/settings.md explains each deviation from the paper.

#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

enum class EdgeSource {
    luma,         // Sobel on the grey image (paper 4.1)
    max_channel,  // strongest of the per-channel Sobel magnitudes: keeps colour-only contrast
};

enum class Compensation {
    frame,  // one offset for the whole difference image (paper 4.1)
    rows,   // each band of rows' light change divided out first: mains flicker's rolling bands
};

enum class SearchWeighting {
    all,     // centre of mass over every pixel of the difference image (paper 4.2)
    strong,  // only pixels at or above a fraction of the strongest difference
};

enum class EstimatorKind {
    ray,               // n-ray casting (paper 3.1)
    iterative_ray,     // iterative n-ray casting (3.2)
    iterative_ny_ray,  // iterative n^y-ray casting (3.3)
    raster,            // iterative n^y-ray casting with m-rasterization (3.4)
};

enum class AreaMode {
    blocks,   // area = selected blocks x m^2, centroid = mean block centre (paper 3.4)
    refined,  // pixels of the selected blocks reachable from the rays without crossing an edge
};

enum class SmoothingKind {
    ema,       // new = w * old + (1 - w) * estimate (paper 4.3; OutputSettings::ema_frame_rate)
    one_euro,  // Casiez, Roussel & Vogel 2012: adaptive low-pass on frame time
};

struct PreprocessSettings {
    int work_width = 160;  // the paper's 160x120 working image
    int work_height = 120;
    // Poisson-disk filter radius in pixels of a 640-wide input; scaled with the input width so
    // that the filter always spans the same part of the scene whatever the camera's size.
    double filter_radius = 5.0;
    // Edge pixel when the Sobel magnitude is over this. The paper's 128 leaves a skin hand over a
    // cluttered room without a closed outline (realworld scenes: 51-93% tracked, 100% at 96).
    int edge_threshold = 96;
    EdgeSource edge_source = EdgeSource::max_channel;
    int compensation_minima = 10;  // distinct minima of the difference image (paper 4.1)
    // The movement value from the grey difference (paper 4.1) or the largest per-channel
    // difference, which sees a skin hand move over a wall of the same brightness. The difference
    // image whose centre of mass picks the target stays the grey one either way.
    EdgeSource movement_source = EdgeSource::max_channel;
    // Under mains flicker a rolling shutter reads each band of rows at another phase of the
    // light, so the light changes by band between frames, not by frame: `rows` brings each band
    // of the previous frame to the current one's light before the difference (the paper's
    // offset follows either way).
    Compensation compensation = Compensation::rows;
};

struct EstimatorSettings {
    EstimatorKind kind = EstimatorKind::raster;
    int rays = 16;            // n
    int recasts = 2;          // y: levels of casting; n^y rays in the last level
    int block_size = 8;       // m, in working pixels
    int max_iterations = 10;  // the paper gives no number
    double tolerance = 0.5;   // working pixels; "negligible adjustment"
    AreaMode area_mode = AreaMode::refined;
    // An inner point on an edge first moves to the nearest non-edge pixel this close (working
    // pixels). 0 = never, as in the paper: 3 changed no figure on the development clips.
    int edge_escape = 0;
    // AreaMode::refined: a fill larger than this times the selected blocks' area has leaked
    // through a gap in the outline and is redone within the selected blocks.
    double fill_limit = 1.5;
    // AreaMode::refined: a fill larger than this times the last frame's fill of the same target
    // has leaked too, and is redone within the selected blocks: a hand does not grow by 75% in a
    // frame, a region that runs out through a gap into a shirt or a shelf does. 0 = no such
    // check. 1.25 lost a rendered hand entering the picture; 1.5-1.75 measured the same
    // (docs/settings.md).
    double fill_growth = 1.75;
    // AreaMode::refined: a region that meets the image border in one run of at least
    // extremity_contact pixels, holding at least half of its border pixels, is an arm or a body
    // coming in from outside the picture (fingertips past the border meet it in short runs);
    // its part beyond this share of the
    // farthest pixel's distance from the border crossing is its far end, the target when it
    // moves, and moves at least as densely as the rest (TrackingSettings::extremity_motion).
    // 0 = the whole region, as in the paper. 0.5 takes a rendered hand off its sleeve (0% to
    // 100% tracked) and loses no clip; 0.4 and 0.6 each lose one (docs/settings.md).
    double extremity = 0.5;
    // 3-6 take a rendered forearm in a sleeve (its run along the border under 8 px at 160x120)
    // off the hand, 8 does not; 16 border pixels in all, the earlier rule, missed it
    // (docs/settings.md).
    int extremity_contact = 4;
    // AreaMode::refined: the fill also steps diagonally between two pixels whose colours differ
    // by at most this (sum of |channel difference|), crossing a one-pixel diagonal line of edge
    // pixels. A finger at 160x120 is edge pixels but for a line of its own colour down its
    // middle, cut from the palm by its base's edges only diagonally; a gap in an outline
    // between a hand and a wall or a shirt joins pixels of two colours. 0 = four neighbours
    // only. 15 took the 15 fps hand from 2.45 to 1.35 px; 8-25 measure the same
    // (docs/settings.md).
    int diagonal_tolerance = 15;
    // AreaMode::refined: a region that leaked (fill_limit, fill_growth) or is larger than a
    // target can be (TrackingSettings::max_area) is estimated again from the same inner point
    // on the edges over this Sobel magnitude, and that estimate is taken when it neither leaks
    // nor leaves the target's area range. The outline of a skin hand against a beige wall or in
    // front of a shirt falls under edge_threshold in places, gaps the region runs out through,
    // while a lower edge_threshold everywhere cuts evenly coloured targets and sleeves into
    // pieces. 40 took rendered skin walls at three seeds from 0-42% tracked to 100%; 32-48
    // measure alike elsewhere (docs/settings.md). 0 = never, as in the paper.
    int weak_edge_threshold = 40;
    // AreaMode::refined: a region whose inner point moved more than this many working pixels in
    // one estimate is estimated again on the weaker edges too (weak_edge_threshold), and that
    // estimate is taken where it holds the inner point within this distance. A hand whose
    // fingers meet a wall of its brightness (skin against lilac: 87 apart in the sum of channel
    // differences, nearly all of it hue) runs out between them into the wall, held by shelves
    // all round: no leak, no size too large, but the inner point goes with the region's
    // centroid 30 px into the wall. 16 took the real hand from 82.2% of its frames tracked to
    // 91.8% and changed no rendered clip's tracked share or error; 8-24 measure alike, 32 no
    // longer finds the real hand's wander (docs/settings.md). 0 = never.
    double weak_wander = 16.0;
    // AreaMode::refined: a region whose core (its pixels at least neck_radius from its outside)
    // falls into pieces has run out through a neck narrower than 2 neck_radius + 1 pixels (a
    // gap in the outline) into what lies beyond; it keeps the piece nearest the inner point,
    // with its thin parts (fingers). Not for a region crossing the image border (an arm: the
    // wrist is such a neck; extremity's case). 0 = never, the paper. 3 took a ball past a
    // shelf and a hand past a ball from 1.85 and 1.97 px to 0.57 and 1.28 px and lost no
    // rendered clip; on the click gesture set a target's region no longer runs into the dark
    // gap beside it and dilutes its pushes (seeds 8-12: target pushes 93.4% to 95.5%), and
    // with push_region_jump the region's steps cost no false click there (docs/settings.md).
    int neck_radius = 3;
};

struct TrackingSettings {
    double startup_seconds = 2.0;  // INITIALIZING: the camera's auto-exposure settles
    // Movement thresholds are sums of the compensated difference image over the paper's
    // 19,200 working pixels (averages of 3 and 0.25); Tracker scales them to the working size.
    // The paper searches above 57,600, which a target sliding into view (1,000-20,000 a
    // frame) never reaches. 9,600 (average 0.5) starts on every measured scene within 0.13 s,
    // while still scenes measure 0-42 and brightness jumps 842 (docs/settings.md).
    double search_threshold = 9600.0;
    double idle_threshold = 4800.0;
    double idle_seconds = 2.0;      // TRACKING fails after this long below idle_threshold
    bool keep_still_target = true;  // a still target stays tracked while its colour validates
    // Fractions of the frame (paper 4.2: 2% and 60%). A sphere moving away in the interfering
    // scene is 2.0-2.5% of the frame: 1% keeps it (60% tracked at 2%, 100% at 1%).
    double min_area = 0.01;
    double max_area = 0.60;
    SearchWeighting search_weighting = SearchWeighting::strong;
    double strong_fraction = 0.5;  // for SearchWeighting::strong: share of the maximum
    int color_patch = 5;           // side of the colour-match square, working pixels
    int color_tolerance = 90;      // sum of |channel difference| of the patch means
    // A tracked target around which less than abandon_share of the movement happens, while the
    // whole is over the search threshold, for abandon_seconds is dropped and searched anew: the
    // tracker holds a still part of the scene while the hand moves elsewhere. 0 s = never, as in
    // the paper. 0.3 s: rendered hands that lost their target to a shelf went from 15% and 8%
    // tracked to 68% and 63%, no clip lost a frame; 1 s changed nothing (docs/accuracy.md).
    double abandon_seconds = 0.3;
    double abandon_share = 0.1;
    // ... but not while the target had its share of the movement within abandon_grace seconds:
    // a hand slows at the turn of a wave, and a ball or a person passing behind it is then most
    // of the movement. 0.5 s: a ball crossing behind a rendered hand took the tracker on 4 of 5
    // seeds (50-93% tracked) and takes it on none (95-100%); 0.7 s and 1 s lost the real hand
    // 5 points (docs/settings.md). 0 = from the first frame away, as before.
    double abandon_grace = 0.5;
    // A target with less than abandon_still_share of such a frame's movement around it has
    // none of it: a still part of the scene beside a moving hand (a window frame, a shelf), not
    // a hand at a turn, which still moves a little. Its time away then runs on through the
    // frames at or under the search threshold that follow, which restart it for a target that
    // only fell under abandon_share. 0.02: the real hand 21.5% to 36.5% tracked (a strip of
    // window frame held for 4 s while the hand waved beside it, its surroundings at exactly 0),
    // no rendered clip changed; 0.001 kept most of the strip (docs/settings.md). 0 = off.
    double abandon_still_share = 0.02;
    // An estimate whose area is over max_growth times the last accepted one per 1/30 s (the
    // factor compounds with the time since that estimate) is a merge with something of the
    // target's colour, not the target: the last estimate stands for up to growth_hold seconds.
    // A hand's projection doubles when it comes 29% closer; a push does that in 0.15 s at the
    // quickest. 0 = off, the default and the paper. 2 took the real hand from 21.9% to 28.3%
    // tracked and changed no rendered clip, but in two of the click gesture set's clips whose
    // region flickers between two it held the larger back on every frame, and their pushes
    // never rose (docs/settings.md).
    double max_growth = 0.0;
    double growth_hold = 0.5;
    // A pick not yet estimated around which the difference sums to at least repick_difference
    // grey levels per pixel of the colour patch (color_patch, made odd; the box summed is one
    // pixel wider where the pick falls between pixels) is background the target uncovered: the
    // pick moves to the difference's centre of mass in this frame, for up to repick_seconds
    // after the first pick.
    // At 10 fps a hand entering fast is a smear that has moved 20-40 working pixels a frame; an
    // estimate from the old pick took the wall or the floor and kept it once the hand stopped.
    // 10 and 0.5 s: the click gesture set's target pushes pressed 89.5% -> 92.3% (seed 1) and
    // 87.8% -> 91.2% (seed 2); 0.3 s closed on hands still moving (docs/settings.md). 0 = off,
    // as in the paper.
    int repick_difference = 10;
    double repick_seconds = 0.5;
    // The movement's chain (docs/settings.md): a point that follows where the movement leads
    // from frame to frame, started at the tracker's first target. A tracked centroid farther
    // than follow_movement region radii (sqrt(area / pi), 4 working pixels to follow_radius of
    // the width) from the chain's point, while the disc of that radius plus 4 px around it
    // holds under follow_share of the frame's strong difference, is a region that lost its
    // target (a small hand's region leaks into the body or the window beside it): the centroid
    // reported and the cursor go to the chain's point, the area and the click stay the
    // region's. A pick, and a frame the state machine searches on, take the chain's point where
    // it followed movement on that frame. At 1 / 0.2 / 0.15 the real hand goes from 36.5%
    // tracked at 9.26 px to 82.2% at 3.89 px, the rendered clips at 98% / 1.5 px from 53 of 58
    // to 54, and the click gesture set's pushes stay as they were. A share of 0.3 lost a
    // rendered hand to a person passing behind it; a largest radius of 0.125 (20 px) took the
    // fast scene to 1.64 px, 0.2 (32 px) left the real hand at 79.0%. 0 = off, as in the paper.
    double follow_movement = 1.0;
    double follow_share = 0.2;
    // The largest region radius the follow_movement tests take, as a share of the working width
    // (24 px at 160): a region larger than a hand near the camera may be the body the hand
    // leaked into, with the hand's movement and the chain's point at its edge, inside its disc.
    double follow_radius = 0.15;
    // The far end of a region crossing the border (EstimatorSettings::extremity) becomes the
    // estimate when at least this share of the movement is around it (0.3 lost hd60's hand).
    double extremity_motion = 0.1;
    int recovery_near = 10;  // recovery offsets, working pixels
    int recovery_far = 20;
    // A tracked target whose estimate comes out under min_area tries the recovery points, as
    // after a colour change, instead of being lost (the paper loses it, 4.2). A fast hand's
    // last centroid lands between its fingers or on the background behind it; once lost, a
    // hand that then stops is never searched out again. Rendered fast clips at seeds 7, 13,
    // 17: 97.0%, 93.9%, 83.6% tracked to 100%. A target's first estimate is not recovered: from
    // the search's point a neighbour of its colour took desk and person clips to 0%.
    bool recover_small = true;
    // A target that came in and stopped leaves nothing in the difference of two frames, so a
    // search that missed it as it came in waits for movement that never comes (a hand lost as
    // it entered, then held still for a click). After movement over the search threshold that
    // left no target, once the movement has stayed at or under idle_threshold for
    // change_seconds, SEARCHING picks the centre of mass of what differs from the last quiet
    // frame before that movement. 0 = never, as in the paper.
    double change_seconds = 0.1;
};

struct OutputSettings {
    SmoothingKind smoothing = SmoothingKind::ema;
    double ema_weight = 0.9;  // weight of the old value
    // ema_weight is the weight of 1/ema_frame_rate s of frame time, or of one frame where
    // frames come faster: a frame t seconds after the last weighs the old value
    // ema_weight^max(1, t x ema_frame_rate). The lag in seconds is then never longer than at
    // that rate: a webcam that halves its rate in dim light, or a busy machine that drops
    // frames, does not let a moving hand's pointer trail (at 30 fps and 0.9 the position is 95%
    // of the way in 0.95 s; once a frame at 6 fps it took 4.7 s). A faster camera keeps the
    // paper's weight a frame, and its shorter lag: the push model's travel (ClickSettings::
    // push_travel) was measured on it. 0: once a frame, whatever the interval (paper 4.3).
    double ema_frame_rate = 30.0;
    double one_euro_min_cutoff = 1.0;  // Hz
    double one_euro_beta = 0.5;
    double one_euro_d_cutoff = 1.0;  // Hz
};

struct Settings {
    PreprocessSettings preprocess;
    EstimatorSettings estimator;
    TrackingSettings tracking;
    OutputSettings output;
    PointerSettings pointer;
};

// The paper's system exactly: every deviation above switched back to what the paper says.
Settings paper_settings();

}  // namespace raypoint::core
