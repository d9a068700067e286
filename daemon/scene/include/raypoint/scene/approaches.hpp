// SPDX-License-Identifier: MIT
#pragma once
// Where a clip's target comes closer as fast as a push: the spans in which its distance from
// the camera falls by `closer` (relative: 0.15 = 15% closer) within `within` seconds. The click
// gesture set states its targets for pushes of at least 15% within 0.6 s, so a motion clip's
// path that approaches so fast holds a push by that definition, meant or not: a press there
// is neither a false click nor an answered push. Read off the clip's trajectory (no pixels):
// the target's true distance, not its visible area.

#include <utility>
#include <vector>

#include "raypoint/scene/scene_spec.hpp"

namespace raypoint::scene {

// Seconds of the clip, [from, to]: each span runs from the first frame of such an approach to
// `after` seconds past its last (the press that answers a push comes after it is under way),
// overlapping spans merged, clipped to [from, to]. Sampled at the clip's frame times.
std::vector<std::pair<double, double>> approaches(const SceneSpec& spec, double from, double to,
                                                  double closer, double within, double after);

}  // namespace raypoint::scene
