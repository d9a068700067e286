// SPDX-License-Identifier: MIT
// A control request of any bytes, as the daemon reads it from a client (at most
// control_request_limit of them): a command exactly when its first line is one of the names,
// nothing otherwise, never a crash.

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include "fuzz_target.hpp"
#include "raypoint/control/control_socket.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raypoint::daemon;
    const std::string_view bytes(reinterpret_cast<const char*>(data),
                                 std::min(size, control_request_limit));
    const auto command = parse_control_request(bytes);
    const std::string_view line = bytes.substr(0, bytes.find('\n'));
    const auto named = control_command_from_string(line);
    if (command != named) std::abort();
    if (command && to_string(*command) != line) std::abort();
    return 0;
}
