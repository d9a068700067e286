// SPDX-License-Identifier: MIT
#include "raypoint/output/sink_factory.hpp"

#include "raypoint/output/file_sink.hpp"
#include "raypoint/output/uinput_pointer.hpp"

namespace raypoint::daemon {

std::unique_ptr<EventSink> make_sink(const SinkSpec& spec, const DeviceProfile& profile) {
    switch (spec.kind) {
        case SinkKind::uinput:
            return std::make_unique<UinputPointer>(profile);
        case SinkKind::file:
            return std::make_unique<FileSink>(spec.path, profile);
        case SinkKind::null:
            return std::make_unique<NullSink>();
    }
    return std::make_unique<NullSink>();
}

}  // namespace raypoint::daemon
