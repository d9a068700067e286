// SPDX-License-Identifier: MIT
#pragma once
// The pinhole camera that projects the target: square pixels, principal point at the centre.

namespace raypoint::scene {

struct Camera {
    int width = 0;  // pixels
    int height = 0;
    // A 0.10 m target at 0.6 m spans 20% of the frame's height (a ~45 degree vertical field of
    // view, as low-budget webcams have).
    double focal_px() const { return 1.2 * height; }
    // Pixels per metre of target size at a depth (m).
    double px_per_metre(double depth) const { return focal_px() / depth; }
};

}  // namespace raypoint::scene
