// SPDX-License-Identifier: MIT
#include "raypoint/view/overlay.hpp"

#include <array>

#include <opencv2/imgproc.hpp>

namespace raypoint::view {
namespace {

void draw_background(cv::Mat& frame, const core::TrackerImages& images, BackgroundView view,
                     int edge_threshold) {
    cv::Mat mask;
    switch (view) {
        case BackgroundView::edges:
            cv::compare(images.edges, edge_threshold, mask, cv::CMP_GT);
            cv::resize(mask, mask, frame.size(), 0, 0, cv::INTER_NEAREST);
            frame.setTo(overlay_edge_color, mask);
            return;
        case BackgroundView::difference: {
            // Differences are small (a moving hand: 10-60 of 255): shown 4x, the frame dimmed
            // under them so that still parts go dark.
            cv::Mat amplified;
            images.difference.convertTo(amplified, CV_8U, 4.0);
            cv::resize(amplified, amplified, frame.size(), 0, 0, cv::INTER_NEAREST);
            cv::Mat heat;
            cv::applyColorMap(amplified, heat, cv::COLORMAP_HOT);
            frame.convertTo(frame, -1, 0.35);
            cv::compare(amplified, 0, mask, cv::CMP_GT);
            heat.copyTo(frame, mask);
            return;
        }
    }
}

}  // namespace

void draw_tracker_view(cv::Mat& frame, const core::Tracker& tracker,
                       const core::FrameResult& result, BackgroundView view, int edge_threshold) {
    const core::TrackerImages images = tracker.images();
    const auto& settings = tracker.settings();
    if (images.edges.empty()) return;  // no frame processed yet
    const double sx = static_cast<double>(frame.cols) / settings.preprocess.work_width;
    const double sy = static_cast<double>(frame.rows) / settings.preprocess.work_height;
    // Working pixel centres are at integer coordinates.
    const auto to_frame = [&](cv::Point2f p) {
        return cv::Point(cvRound((p.x + 0.5) * sx), cvRound((p.y + 0.5) * sy));
    };
    const auto fraction_to_frame = [&](cv::Point2d p) {
        return cv::Point(cvRound(p.x * frame.cols), cvRound(p.y * frame.rows));
    };
    draw_background(frame, images, view, edge_threshold);

    const bool tracking = result.has_target && result.area.has_value();
    const core::EstimatorTrace& trace = images.trace;
    if (tracking && trace.block_size > 0) {
        cv::Mat overlay = frame.clone();
        for (int by = 0; by < trace.blocks_high; ++by) {
            for (int bx = 0; bx < trace.blocks_wide; ++bx) {
                if (trace.blocks[by * trace.blocks_wide + bx] == 0) continue;
                const cv::Point2f corner(static_cast<float>(bx * trace.block_size) - 0.5F,
                                         static_cast<float>(by * trace.block_size) - 0.5F);
                const cv::Point2f size(static_cast<float>(trace.block_size),
                                       static_cast<float>(trace.block_size));
                cv::rectangle(overlay, to_frame(corner), to_frame(corner + size),
                              overlay_block_color, cv::FILLED);
            }
        }
        cv::addWeighted(overlay, 0.35, frame, 0.65, 0.0, frame);
    }
    if (tracking) {
        for (const auto& ray : trace.rays) {
            cv::line(frame, to_frame(ray.from), to_frame(ray.to), overlay_ray_color, 1,
                     cv::LINE_AA);
        }
    }
    if (result.recovery_from) {
        // The 16 places RECOVERING tried (state_machine.cpp): near and far, 8 directions.
        static constexpr std::array<std::array<int, 2>, 8> directions{
            {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
        const cv::Point2d from = *result.recovery_from;
        for (const int offset : {settings.tracking.recovery_near, settings.tracking.recovery_far}) {
            for (const auto& d : directions) {
                const cv::Point2d point(
                    from.x + d[0] * offset / static_cast<double>(settings.preprocess.work_width),
                    from.y + d[1] * offset / static_cast<double>(settings.preprocess.work_height));
                cv::circle(frame, fraction_to_frame(point), 4, overlay_recovery_color, 2,
                           cv::LINE_AA);
            }
        }
        cv::drawMarker(frame, fraction_to_frame(from), overlay_recovery_color, cv::MARKER_DIAMOND,
                       14, 2);
    }
    if (result.has_target) {
        cv::circle(frame, fraction_to_frame(result.inner), 6, overlay_inner_color, 2, cv::LINE_AA);
        // The raw centroid (paper 3), not the smoothed position: what the estimator found.
        cv::drawMarker(frame, fraction_to_frame(result.centroid), overlay_centroid_color,
                       cv::MARKER_CROSS, centroid_marker_size, 2, cv::LINE_8);
    }
}

}  // namespace raypoint::view
