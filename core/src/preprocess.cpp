// SPDX-License-Identifier: MIT
// Frame preprocessing (paper 4.1): the stages composed, each on the images of the one before.

#include "raypoint/core/preprocess.hpp"

namespace raypoint::core {

Preprocessor::Preprocessor(const PreprocessSettings& settings, StageInstructions instructions)
    : filter_(settings, instructions.filter),
      edges_(settings, instructions.edges),
      difference_(settings) {}

void Preprocessor::set_instructions(StageInstructions instructions) noexcept {
    filter_.set_instructions(instructions.filter);
    edges_.set_instructions(instructions.edges);
}

bool Preprocessor::process(const FrameView& frame, Edges edges) noexcept {
    if (!filter(frame)) return false;
    if (edges == Edges::computed) compute_edges();
    compute_difference();
    return true;
}

// A frame that is not read leaves every image as it was, the edges' currency included.
bool Preprocessor::filter(const FrameView& frame) noexcept {
    if (!filter_.apply(frame)) return false;
    edges_current_ = false;
    return true;
}

void Preprocessor::compute_edges() noexcept {
    edges_.compute(filter_.gray(), filter_.planes());
    edges_current_ = true;
}

// The first frame of a geometry has nothing to compare with: no difference, no movement.
void Preprocessor::compute_difference() noexcept {
    if (!filter_.has_previous()) {
        difference_.reset();
        return;
    }
    difference_.compute(filter_.gray(), filter_.previous_gray(), filter_.color(),
                        filter_.previous_color());
}

}  // namespace raypoint::core
