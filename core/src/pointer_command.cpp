// SPDX-License-Identifier: MIT
#include "raypoint/core/pointer_command.hpp"

namespace raypoint::core {

bool PointerCommand::add(Button button, bool pressed) noexcept {
    if (change_count >= max_changes) return false;
    changes[static_cast<std::size_t>(change_count++)] = ButtonChange{button, pressed};
    return true;
}

std::string_view to_string(Button button) noexcept {
    switch (button) {
        case Button::left:
            return "left";
        case Button::right:
            return "right";
        case Button::middle:
            return "middle";
    }
    return "?";
}

}  // namespace raypoint::core
