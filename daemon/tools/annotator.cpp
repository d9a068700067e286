// SPDX-License-Identifier: MIT
#include "annotator.hpp"

#include <string>

#include <opencv2/imgproc.hpp>

namespace raypoint::daemon {

void annotate(cv::Mat& frame, const core::Tracker& tracker, const core::FrameResult& result) {
    const core::TrackerImages images = tracker.images();
    const auto& settings = tracker.settings().preprocess;
    const double sx = static_cast<double>(frame.cols) / settings.work_width;
    const double sy = static_cast<double>(frame.rows) / settings.work_height;
    // Working pixel centres are at integer coordinates.
    const auto to_frame = [&](cv::Point2f p) {
        return cv::Point(cvRound((p.x + 0.5) * sx), cvRound((p.y + 0.5) * sy));
    };

    // Edge pixels tinted green.
    cv::Mat edge_mask;
    cv::compare(images.edges, settings.edge_threshold, edge_mask, cv::CMP_GT);
    cv::Mat big_mask;
    cv::resize(edge_mask, big_mask, frame.size(), 0, 0, cv::INTER_NEAREST);
    frame.setTo(cv::Scalar(0, 200, 0), big_mask);

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
                              cv::Scalar(255, 128, 0), cv::FILLED);
            }
        }
        cv::addWeighted(overlay, 0.35, frame, 0.65, 0.0, frame);
    }
    if (tracking) {
        for (const auto& ray : trace.rays) {
            cv::line(frame, to_frame(ray.from), to_frame(ray.to), cv::Scalar(0, 255, 255), 1,
                     cv::LINE_AA);
        }
    }
    if (result.has_target) {
        const cv::Point2d inner(result.inner.x * frame.cols, result.inner.y * frame.rows);
        const cv::Point2d centroid(result.centroid.x * frame.cols, result.centroid.y * frame.rows);
        cv::circle(frame, inner, 6, cv::Scalar(255, 0, 255), 2, cv::LINE_AA);
        cv::drawMarker(frame, centroid, cv::Scalar(0, 0, 255), cv::MARKER_CROSS, 18, 2);
    }
    std::string label(core::to_string(result.state));
    if (result.area) label += "  area " + std::to_string(*result.area).substr(0, 5);
    if (result.recovered) label += "  recovered";
    cv::putText(frame, label, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0), 4,
                cv::LINE_AA);
    cv::putText(frame, label, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(255, 255, 255), 2,
                cv::LINE_AA);
}

}  // namespace raypoint::daemon
