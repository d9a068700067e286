#include "raypoint/core/pointer_settings.hpp"

namespace raypoint::core {

std::string_view pointer_settings_problem(const PointerSettings& settings) noexcept {
    const MotionSettings& motion = settings.motion;
    if (!(motion.active_left < motion.active_right)) {
        return "pointer.active_left must be below pointer.active_right";
    }
    if (!(motion.active_top < motion.active_bottom)) {
        return "pointer.active_top must be below pointer.active_bottom";
    }
    const ClickSettings& click = settings.click;
    if (!(click.release_rise < click.press_rise)) {
        return "click.release_rise must be below click.press_rise, or a press releases at once";
    }
    if (!(click.start_rise < click.press_rise)) {
        return "click.start_rise must be below click.press_rise: a push begins before it presses";
    }
    return {};
}

}  // namespace raypoint::core
