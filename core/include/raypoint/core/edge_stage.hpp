// SPDX-License-Identifier: MIT
#pragma once
// The second stage of frame preprocessing (paper 4.1): the Sobel edge image of the working
// image, its magnitude thresholded (128 in the paper; PreprocessSettings::edge_threshold).

#include <vector>

#include <opencv2/core.hpp>

#include "raypoint/core/instruction_set.hpp"
#include "raypoint/core/settings.hpp"

namespace raypoint::core {

class EdgeStage {
  public:
    explicit EdgeStage(const PreprocessSettings& settings,
                       InstructionSet instructions = best_instruction_set());

    // Recomputes the magnitude and edge images from `grey` (CV_8U, the working size) or, for
    // EdgeSource::max_channel, from `planes` (CV_8U, the B, G and R planes one above the
    // other: three working heights; FilterStage::planes()). The other image is not read.
    void compute(const cv::Mat& grey, const cv::Mat& planes) noexcept;

    // Takes effect from the next compute(); every set gives the same images.
    void set_instructions(InstructionSet instructions) noexcept { instructions_ = instructions; }
    InstructionSet instructions() const noexcept { return instructions_; }

    const cv::Mat& magnitude() const noexcept { return magnitude_; }  // CV_8U Sobel magnitude
    // CV_8U: the magnitude where it is over the edge threshold, 0 elsewhere.
    const cv::Mat& edges() const noexcept { return edges_; }

  private:
    EdgeSource source_;
    int threshold_;
    InstructionSet instructions_;
    std::vector<int> squared_channels_;  // one row of squared Sobel magnitudes, per plane
    cv::Mat magnitude_;
    cv::Mat edges_;
};

}  // namespace raypoint::core
