// SPDX-License-Identifier: MIT
#include "raypoint/core/dwell_clicker.hpp"

#include <cmath>

namespace raypoint::core {

std::string_view to_string(DwellState state) noexcept {
    switch (state) {
        case DwellState::inactive:
            return "inactive";
        case DwellState::waiting:
            return "waiting";
        case DwellState::clicked:
            return "clicked";
    }
    return "?";
}

DwellClicker::DwellClicker(const DwellSettings& settings) noexcept : settings_(settings) {}

bool DwellClicker::moved(cv::Point2d where) const noexcept {
    return std::hypot(where.x - anchor_.x, where.y - anchor_.y) > settings_.radius;
}

bool DwellClicker::step(Timestamp timestamp, std::optional<cv::Point2d> where,
                        bool ready) noexcept {
    if (!where || !ready) {
        state_ = DwellState::inactive;
        return false;
    }
    switch (state_) {
        case DwellState::inactive:
            state_ = DwellState::waiting;
            anchor_ = *where;
            since_ = timestamp;
            return false;
        case DwellState::waiting:
            if (moved(*where)) {
                anchor_ = *where;
                since_ = timestamp;
                return false;
            }
            if (static_cast<double>(timestamp - since_) / 1e6 >= settings_.seconds) {
                state_ = DwellState::clicked;
                return true;
            }
            return false;
        case DwellState::clicked:
            if (moved(*where)) {
                state_ = DwellState::waiting;
                anchor_ = *where;
                since_ = timestamp;
            }
            return false;
    }
    return false;
}

}  // namespace raypoint::core
