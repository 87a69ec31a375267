#pragma once
// Shared helpers for the gesture tests: synthetic touch frames on a 1920x1080 picture, and the
// engine's camera to see where a point of the stone lands on screen.

#include <cmath>
#include <initializer_list>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gestures/gesture_controller.hpp"
#include "picture/camera.hpp"

namespace gem::kiosk::test {

inline constexpr double kWidth = 1920.0;
inline constexpr double kHeight = 1080.0;
// The default gain: 180 degrees per picture height of 1080 px.
inline constexpr double kDegreesPerPx = 180.0 / 1080.0;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

inline TouchFrame frame(double time_s, std::initializer_list<Contact> contacts) {
    return TouchFrame{time_s, contacts};
}

inline TouchFrame lift(double time_s) {
    return TouchFrame{time_s, {}};
}

inline GestureController make_controller(const ViewState& start,
                                         const GestureOptions& options = {}) {
    GestureController controller(options, start);
    controller.set_picture_size({kWidth, kHeight});
    return controller;
}

// One finger `id` moving in a straight line from `from` to `to` in `steps` frames `dt_s`
// apart, the first at `t0_s` (at `from`); returns the time of the last frame.
inline double move_finger(GestureController& controller, int id, glm::dvec2 from, glm::dvec2 to,
                          double t0_s, double dt_s, int steps) {
    for (int i = 0; i <= steps; ++i) {
        const double f = static_cast<double>(i) / steps;
        controller.on_event(frame(t0_s + i * dt_s, {Contact{id, from + f * (to - from)}}));
    }
    return t0_s + steps * dt_s;
}

inline Camera camera_for(const ViewState& view) {
    CameraSettings settings;
    settings.azimuth_deg = view.azimuth_deg;
    settings.elevation_deg = view.elevation_deg;
    settings.roll_deg = view.roll_deg;
    settings.zoom = view.zoom;
    // A stone of bounding radius 1 mm.
    return Camera::make(settings, 1.0, static_cast<int>(kWidth), static_cast<int>(kHeight)).value();
}

// Where the stone-frame point `p` appears in the picture (pixels, y down): the orthographic
// projection along camera.forward(), inverting Camera::ray.
inline glm::dvec2 project(const ViewState& view, glm::dvec3 p) {
    const Camera camera = camera_for(view);
    return {0.5 * kWidth + glm::dot(p, camera.right()) / camera.pixel_size(),
            0.5 * kHeight - glm::dot(p, camera.up()) / camera.pixel_size()};
}

// The point of a stone of radius 0.8 mm nearest the camera: its front surface.
inline glm::dvec3 front_point(const ViewState& view) {
    return -0.8 * camera_for(view).forward();
}

// Azimuth and roll are kept in [-180, 180): compare them round the circle.
inline double circular_difference(double a_deg, double b_deg) {
    return std::remainder(a_deg - b_deg, 360.0);
}

}  // namespace gem::kiosk::test
