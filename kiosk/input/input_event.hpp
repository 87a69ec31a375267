#pragma once
// What the input layer hands to the gestures: after every complete evdev frame (SYN_REPORT)
// of a touchscreen, the full list of fingers down, in picture pixels (after calibration and
// rotation: (0, 0) is the top-left corner of the picture as the shopper sees it); a mouse
// with its left button down counts as one finger, its wheel as zoom steps. Times are
// CLOCK_MONOTONIC seconds (devices are switched to that clock; replays are re-timed to it).

#include <variant>
#include <vector>

#include <glm/vec2.hpp>

namespace gem::kiosk {

struct Contact {
    int id = 0;  // stable while the finger stays down (tracking id, or slot for protocol A)
    glm::dvec2 position{0.0};
};

struct TouchFrame {
    double time_s = 0.0;
    std::vector<Contact> contacts;  // empty: every finger lifted
};

struct WheelStep {
    double time_s = 0.0;
    double steps = 0.0;  // positive: away from the user (zoom in)
    glm::dvec2 position{0.0};
};

using InputEvent = std::variant<TouchFrame, WheelStep>;

}  // namespace gem::kiosk
