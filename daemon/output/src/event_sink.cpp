// SPDX-License-Identifier: MIT
#include "raypoint/output/event_sink.hpp"

namespace raypoint::daemon {

void NullSink::emit(const core::PointerCommand& /*command*/,
                    core::Timestamp /*timestamp*/) noexcept {}

void NullSink::release_all(core::Timestamp /*timestamp*/) noexcept {}

}  // namespace raypoint::daemon
