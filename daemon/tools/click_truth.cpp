// SPDX-License-Identifier: MIT
#include "click_truth.hpp"

#include <fstream>
#include <sstream>

#include "input_error.hpp"

namespace raypoint::daemon {

ClickTruth read_click_truth(const std::string& truth) {
    ClickTruth result;
    std::ifstream in(truth);
    if (!in) throw InputError(truth + ": cannot open the click truth file");
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::string kind;
        if (!(words >> kind)) continue;
        if (kind == "motion" || kind == "approach") {
            double from = 0;
            double to = 0;
            if (!(words >> from >> to) || to <= from) {
                std::string message = truth;
                message.append(":").append(std::to_string(number)).append(": ").append(kind);
                throw InputError(message.append(": expected FROM TO in seconds, FROM < TO"));
            }
            (kind == "motion" ? result.motion_spans : result.approaches).emplace_back(from, to);
            continue;
        }
        scene::IntendedClick click;
        if (kind == "click") {
            click.kind = scene::GestureKind::click;
        } else if (kind == "drag") {
            click.kind = scene::GestureKind::drag;
        } else if (kind == "right") {
            click.kind = scene::GestureKind::right;
        } else if (kind == "double") {
            click.kind = scene::GestureKind::double_click;
        } else if (kind == "scroll_up") {
            click.kind = scene::GestureKind::scroll_up;
        } else if (kind == "scroll_down") {
            click.kind = scene::GestureKind::scroll_down;
        } else {
            std::string message = truth;
            message.append(":").append(std::to_string(number)).append(": ");
            message += kind;
            message +=
                ": unknown line (allowed: click, drag, right, double, scroll_up, scroll_down, "
                "motion, approach)";
            throw InputError(message);
        }
        if (!(words >> click.start >> click.press >> click.release) ||
            !(click.start <= click.press && click.press <= click.release)) {
            throw InputError(truth + ":" + std::to_string(number) +
                             ": expected START PRESS RELEASE in seconds, in that order");
        }
        words >> click.depth >> click.seconds;  // optional
        result.clicks.push_back(click);
    }
    return result;
}

}  // namespace raypoint::daemon
