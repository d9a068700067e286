// SPDX-License-Identifier: MIT
#include "raypoint/core/settings.hpp"

namespace raypoint::core {

Settings paper_settings() {
    Settings settings;
    settings.preprocess.edge_source = EdgeSource::luma;
    settings.preprocess.movement_source = EdgeSource::luma;
    settings.preprocess.edge_threshold = 128;
    settings.tracking.search_threshold = 57600.0;
    settings.tracking.min_area = 0.02;
    settings.estimator.area_mode = AreaMode::blocks;
    settings.tracking.keep_still_target = false;
    settings.tracking.abandon_seconds = 0.0;
    settings.tracking.search_weighting = SearchWeighting::all;
    settings.output.smoothing = SmoothingKind::ema;
    return settings;
}

}  // namespace raypoint::core
