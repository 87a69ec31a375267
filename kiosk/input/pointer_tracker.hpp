#pragma once
// A mouse on the kiosk: it moves a pointer over the picture (one count of REL_X / REL_Y is one
// picture pixel, the pointer clamped to the picture); while its left button is down it is one
// finger at the pointer, so the gestures need no mouse code; its wheel gives zoom steps.

#include <linux/input.h>

#include <vector>

#include <glm/vec2.hpp>

#include "input/input_event.hpp"

namespace gem::kiosk {

class PointerTracker {
  public:
    // The pointer starts at the picture's centre.
    explicit PointerTracker(glm::dvec2 picture_size);

    // Appends what a completed frame (SYN_REPORT) produced: a TouchFrame while the button is
    // down and something changed, an empty one when it is released, a WheelStep for the wheel.
    // Returns true when the SYN_REPORT ending a SYN_DROPPED discard arrived: then call
    // resynchronise() with the device's button state.
    bool feed(const input_event& event, glm::dvec2 picture_size, std::vector<InputEvent>& out);
    void resynchronise(bool left_button, double time_s, std::vector<InputEvent>& out);

    glm::dvec2 position() const { return position_; }
    bool button_down() const { return button_down_; }

  private:
    glm::dvec2 position_;
    glm::dvec2 picture_size_;
    bool button_down_ = false;
    bool button_changed_ = false;
    bool moved_ = false;
    double wheel_steps_ = 0.0;
    bool discarding_ = false;
};

double event_time_s(const input_event& event);

}  // namespace gem::kiosk
