// SPDX-License-Identifier: MIT
#pragma once
// Counting heap allocations, for the "no allocation per frame" promises (tracker.hpp,
// event_sink.hpp). allocation_counter.cpp replaces the global operator new and delete for the
// whole test executable that links it; they count only between start and stop.

namespace raypoint::test {

void start_counting_allocations() noexcept;
long stop_counting_allocations() noexcept;  // the allocations since start

// Counts the allocations `work` makes.
template <typename Work>
long allocations_during(Work&& work) {
    start_counting_allocations();
    work();
    return stop_counting_allocations();
}

}  // namespace raypoint::test
