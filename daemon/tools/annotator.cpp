// SPDX-License-Identifier: MIT
#include "annotator.hpp"

#include <string>

#include <opencv2/imgproc.hpp>

#include "raypoint/view/overlay.hpp"

namespace raypoint::daemon {

void annotate(cv::Mat& frame, const core::Tracker& tracker, const core::FrameResult& result) {
    view::draw_tracker_view(frame, tracker, result, view::BackgroundView::edges,
                            tracker.settings().preprocess.edge_threshold);
    std::string label(core::to_string(result.state));
    if (result.area) label += "  area " + std::to_string(*result.area).substr(0, 5);
    if (result.recovered) label += "  recovered";
    cv::putText(frame, label, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(0, 0, 0), 4,
                cv::LINE_AA);
    cv::putText(frame, label, {10, 28}, cv::FONT_HERSHEY_SIMPLEX, 0.8, cv::Scalar(255, 255, 255), 2,
                cv::LINE_AA);
}

}  // namespace raypoint::daemon
