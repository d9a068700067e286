// SPDX-License-Identifier: MIT
#include "raypoint/core/settings.hpp"

namespace raypoint::core {

Settings paper_settings() {
    Settings settings;
    settings.preprocess.edge_source = EdgeSource::luma;
    settings.preprocess.movement_source = EdgeSource::luma;
    settings.preprocess.compensation = Compensation::frame;
    settings.preprocess.edge_threshold = 128;
    settings.tracking.search_threshold = 57600.0;
    settings.tracking.min_area = 0.02;
    settings.estimator.area_mode = AreaMode::blocks;
    settings.estimator.extremity = 0.0;
    settings.estimator.weak_edge_threshold = 0;
    settings.estimator.weak_wander = 0.0;
    settings.estimator.diagonal_tolerance = 0;
    settings.estimator.fill_growth = 0.0;
    settings.estimator.neck_radius = 0;
    settings.tracking.keep_still_target = false;
    settings.tracking.recover_small = false;
    settings.tracking.change_seconds = 0.0;
    settings.tracking.abandon_seconds = 0.0;
    settings.tracking.abandon_grace = 0.0;
    settings.tracking.abandon_still_share = 0.0;
    settings.tracking.repick_difference = 0;
    settings.tracking.follow_movement = 0.0;
    settings.tracking.search_weighting = SearchWeighting::all;
    settings.output.smoothing = SmoothingKind::ema;
    settings.output.ema_frame_rate = 0.0;
    // The paper has no clicks; the preset keeps the click by depth it was first measured with
    // (docs/pointer.md), whatever the defaults become.
    ClickSettings& click = settings.pointer.click;
    click.start_rise = 0.05;
    click.press_rise = 0.20;
    click.release_rise = 0.10;
    click.push_seconds = 0.25;
    click.press_hold_seconds = 0.0;
    click.jump_hold_seconds = 0.0;
    click.release_drop = 0.0;
    click.release_share = 0.0;
    click.release_raw_seconds = 0.0;
    click.glitch_jump = 0.0;
    click.glitch_leap = 0.0;
    click.glitch_light = 0.0;
    click.glitch_return_seconds = 0.0;
    click.push_travel = 0.0;
    click.travel_hold_seconds = 0.0;
    click.push_region_jump = 0.0;
    click.push_dip = 0.0;
    click.refractory_seconds = 0.3;
    click.drag_seconds = 0.8;
    click.baseline_seconds = 1.0;
    click.settle_seconds = 0.0;
    click.hold_settle_seconds = 0.0;
    click.hold_rise = 0.05;
    click.hold_flicker_seconds = 0.0;
    return settings;
}

}  // namespace raypoint::core
