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

bool Preprocessor::process(const FrameView& frame) noexcept {
    if (!filter(frame)) return false;
    compute_edges();
    compute_difference();
    return true;
}

bool Preprocessor::filter(const FrameView& frame) noexcept {
    return filter_.apply(frame);
}

void Preprocessor::compute_edges() noexcept {
    edges_.compute(filter_.gray(), filter_.planes());
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
