// SPDX-License-Identifier: MIT
#pragma once
// What a rendered clip shows: the target, the background, the camera's conditions and the
// target's path. Plain data; Renderer checks it and presets.hpp has ready-made ones.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace raypoint::scene {

enum class Target {
    sphere,  // black matte sphere with soft shading (the paper's ideal, low light, interfering)
    hand,    // flat hand with five spread fingers: non-convex, evenly coloured
};

enum class Background {
    plain,      // a slightly uneven white board
    cluttered,  // a procedural room (shelves, furniture, posters, textures), fixed by the seed
    skin_wall,  // a wall painted warm beige or pink, near a skin's colour, with a few things on it
    desk,       // a wooden desk seen from above: planks, soft grain, warm tones, a few things
    photo,      // SceneSpec::background_photo, scaled to cover the frame, cropped by the seed
};

// A point of an explicit path. x, y: the target's centre as fractions of the frame's width and
// height (0, 0 = top-left corner; the hand's centre is the middle of its upright bounding box);
// depth: metres from the camera; angle: in-plane rotation in radians, clockwise on screen
// (the sphere ignores it).
struct Keyframe {
    double t = 0;  // seconds from the start of the clip
    double x = 0;
    double y = 0;
    double depth = 0;
    double angle = 0;
    double spread = 1;  // a hand's fingers: fanned (1), side by side (0), a fist (-1)
};

// The target stands exactly still on its path over [start, start + seconds]; it slows down
// during the 0.25 s before and speeds up during the 0.25 s after.
struct Hold {
    double start = 0;  // s
    double seconds = 0;
};

// Grey levels 0..255 of a surface facing the light, as this camera sees it at full light.
struct Colour {
    double b = 0;
    double g = 0;
    double r = 0;
};

struct SceneSpec {
    std::string name;
    Target target = Target::sphere;
    Background background = Background::plain;
    std::string background_photo;  // Background::photo: an image file OpenCV reads
    int width = 640;               // pixels
    int height = 480;
    double fps = 30;
    double seconds = 6.0;
    double empty_seconds = 2.5;  // empty scene before the target enters (the tracker's start-up)
    double noise_sigma = 1.5;    // Gaussian sensor noise, grey levels, per pixel and channel
    double blur = 0.3;           // exposure time as a fraction of the frame interval (motion blur)
    int jpeg_quality = 0;        // 0 = none, else every frame goes through JPEG at this quality
    std::vector<double> brightness_jumps;  // times (s) of sudden auto-exposure gain changes
    // Each jump divides (1st, 3rd, ...) or multiplies (2nd, 4th, ...) the gain by
    // 1 + brightness_jump, so the gain alternates between 1 and 1 / (1 + brightness_jump).
    double brightness_jump = 0.25;
    // Mains flicker under fluorescent or cheap LED light: the light swings by +-flicker_depth at
    // flicker_hz (twice the mains frequency: 100 Hz in Europe, 120 in America), and the rolling
    // shutter reads the rows top to bottom over readout_seconds, so the swing shows as
    // horizontal bands that roll through the picture from frame to frame.
    double flicker_depth = 0.0;
    double flicker_hz = 100.0;
    double readout_seconds = 0.025;
    // The target too is read row by row over readout_seconds: moving sideways it shears, moving
    // down it stretches (the rolling shutter's skew). Off: the target is drawn at one time.
    bool rolling_shutter = false;
    // Slow auto-exposure and white-balance hunting: the gain swings by +-exposure_drift and each
    // channel's by +-white_balance_drift (blue and red in opposite phase, green between) over
    // drift_period seconds.
    double exposure_drift = 0.0;
    double white_balance_drift = 0.0;
    double drift_period = 4.0;
    double darkness = 1.0;  // light level multiplier (the lowlight preset: 0.42, noise 8)
    double speed = 1.0;     // scales the default trajectory's speed (not an explicit path's)
    // Empty: a default smooth trajectory that enters from the right edge at empty_seconds
    // (over 0.6 s), wanders in x and y and varies depth so that the target covers about 3.5%
    // (far) to 10% (near) of the frame. Otherwise the target follows these keyframes (a
    // smooth cubic through them, held at the first and last) from empty_seconds on.
    std::vector<Keyframe> path;
    std::vector<Hold> holds;
    // Start times (s) of pushes toward the camera (click gestures): depth eases down by
    // push_depth (relative) over push_seconds, stays 0.1 s, and eases back over push_seconds.
    std::vector<double> pushes;
    double push_depth = 0.25;
    double push_seconds = 0.3;
    // Pushes each with its own shape (gesture_set.hpp draws them from ranges), on top of
    // `pushes`: depth eases down by `depth` (relative) over `seconds`, stays `hold` s, and eases
    // back over `seconds`.
    struct Push {
        double start = 0;  // s
        double depth = 0.25;
        double seconds = 0.3;
        double hold = 0.1;
    };
    std::vector<Push> shaped_pushes;
    // Sphere diameter / hand height in metres. The pinhole camera has a focal length of
    // 1.2 x height pixels: a 0.10 m target at 0.6 m spans 20% of the frame's height.
    double target_size_m = 0.10;
    // Empty: a matte black sphere; a blue paper hand on the plain board; a skin-coloured
    // hand in the cluttered room.
    std::optional<Colour> target_colour;
    // The hand's forearm in a sleeve of this colour, from the wrist along the hand's axis out of
    // the frame. Drawn behind the hand and moving with it; not part of the truth (a pointer
    // follows the hand). Empty: no arm.
    std::optional<Colour> sleeve_colour;
    // A person sitting behind the target (head, neck, shoulders, shirt), skin of the target's
    // colour family, breathing and turning the head a little as a person at a desk does; part
    // of the background, not of the truth.
    bool person = false;
    // A second object passing behind the target: a matte ball of pass_size (its diameter, a
    // fraction of the frame's height) crossing the picture at pass_y (its centre, a fraction
    // of the height) in pass_seconds, starting at each of these times (s), right to left, then
    // left to right, alternately. Part of the background, not of the truth. Empty colour: dark
    // grey.
    std::vector<double> passes;
    double pass_seconds = 1.5;
    double pass_size = 0.25;
    double pass_y = 0.5;
    std::optional<Colour> pass_colour;
    std::uint32_t seed = 1;  // background layout, default trajectory and noise
};

}  // namespace raypoint::scene
