#include "input/pointer_tracker.hpp"

#include <algorithm>

#include <glm/common.hpp>

namespace gem::kiosk {

double event_time_s(const input_event& event) {
    return static_cast<double>(event.input_event_sec) +
           static_cast<double>(event.input_event_usec) * 1e-6;
}

PointerTracker::PointerTracker(glm::dvec2 picture_size)
    : position_(picture_size * 0.5), picture_size_(picture_size) {}

bool PointerTracker::feed(const input_event& event, glm::dvec2 picture_size,
                          std::vector<InputEvent>& out) {
    // A new picture size (a mode change) keeps the pointer at the same relative spot.
    if (picture_size != picture_size_ && picture_size_.x > 0.0 && picture_size_.y > 0.0)
        position_ = position_ / picture_size_ * picture_size;
    picture_size_ = picture_size;
    if (event.type == EV_SYN && event.code == SYN_DROPPED) {
        // Documentation/input/event-codes.rst: ignore everything up to the next SYN_REPORT.
        discarding_ = true;
        return false;
    }
    if (discarding_) {
        if (event.type != EV_SYN || event.code != SYN_REPORT) return false;
        moved_ = button_changed_ = false;
        wheel_steps_ = 0.0;
        return true;
    }
    if (event.type == EV_REL) {
        // REL_WHEEL_HI_RES repeats REL_WHEEL in 1/120 notches; counting both would double.
        if (event.code == REL_X) position_.x += event.value;
        if (event.code == REL_Y) position_.y += event.value;
        if (event.code == REL_X || event.code == REL_Y) moved_ = true;
        if (event.code == REL_WHEEL) wheel_steps_ += event.value;
    } else if (event.type == EV_KEY && event.code == BTN_LEFT) {
        const bool down = event.value != 0;
        button_changed_ = button_changed_ || down != button_down_;
        button_down_ = down;
    } else if (event.type == EV_SYN && event.code == SYN_REPORT) {
        position_ = glm::clamp(position_, glm::dvec2(0.0), picture_size_);
        const double time_s = event_time_s(event);
        if (wheel_steps_ != 0.0) out.push_back(WheelStep{time_s, wheel_steps_, position_});
        if (button_down_ && (moved_ || button_changed_)) {
            out.push_back(TouchFrame{time_s, {Contact{0, position_}}});
        } else if (!button_down_ && button_changed_) {
            out.push_back(TouchFrame{time_s, {}});
        }
        moved_ = button_changed_ = false;
        wheel_steps_ = 0.0;
    }
    return false;
}

void PointerTracker::resynchronise(bool left_button, double time_s, std::vector<InputEvent>& out) {
    discarding_ = false;
    if (left_button == button_down_) return;
    button_down_ = left_button;
    if (button_down_) {
        out.push_back(TouchFrame{time_s, {Contact{0, position_}}});
    } else {
        out.push_back(TouchFrame{time_s, {}});
    }
}

}  // namespace gem::kiosk
