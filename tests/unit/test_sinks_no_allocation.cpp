// SPDX-License-Identifier: MIT
// The per-frame path of the sinks does not allocate (event_sink.hpp), counted by the replaced
// global operator new of tests/support/allocation_counter.cpp. stdio's own buffer is malloc'd, not
// new'd: FileSink hands stdio a buffer up front.

#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <unistd.h>
#include "allocation_counter.hpp"

#include "raypoint/output/event_sink.hpp"
#include "raypoint/output/file_sink.hpp"
#include "raypoint/output/pointer_events.hpp"

namespace raypoint::daemon {
namespace {

using raypoint::test::allocations_during;

core::PointerCommand busy_command(int i) {
    core::PointerCommand command;
    command.dx = i;
    command.dy = -i;
    command.has_absolute = true;
    command.abs_x = 100 * i;
    command.abs_y = 50 * i;
    command.wheel = i % 3 - 1;
    command.add(core::Button::left, i % 2 == 0);
    command.add(core::Button::right, true);
    command.add(core::Button::right, false);
    return command;
}

TEST(NoAllocation, TheCounterCounts) {
    std::vector<int> grown;
    EXPECT_GE(allocations_during([&] { grown.resize(1000); }), 1);
    EXPECT_EQ(allocations_during([] {}), 0);
}

TEST(NoAllocation, EncoderAndFileSinkPerCommand) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("raypoint-test-sinks-" + std::to_string(::getpid()) + "-no-allocation.txt");
    for (const core::PointerMode mode :
         {core::PointerMode::relative, core::PointerMode::absolute}) {
        PointerEncoder encoder(DeviceProfile{mode, 65535});
        FileSink sink(path, DeviceProfile{mode, 65535});
        NullSink null;
        sink.emit(busy_command(0), 0);  // warm-up: first-call work is not per-frame
        const long count = allocations_during([&] {
            for (int i = 1; i < 100; ++i) {
                const EventBatch batch = encoder.encode(busy_command(i));
                EXPECT_FALSE(batch.empty());
                sink.emit(busy_command(i), i * 33333);
                null.emit(busy_command(i), i * 33333);
            }
            sink.release_all(100 * 33333);
        });
        EXPECT_EQ(count, 0);
        EXPECT_EQ(sink.last_error(), 0);
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace raypoint::daemon
