#pragma once
// From a touch position normalised on the device's axes to picture pixels, in three steps:
//
// 1. Calibration, libinput's convention (LIBINPUT_CALIBRATION_MATRIX, see libinput's
//    "Static device configuration via udev" and libinput_device_config_calibration_set_matrix()
//    in libinput.h): on coordinates normalised to [0, 1] of the device's axes,
//    u' = a u + b v + c, v' = d u + e v + f for the matrix {a, b, c, d, e, f}.
// 2. Rotation R (clockwise degrees, 0/90/180/270) from the picture to the panel, the same
//    quantity as Display::rotation_deg(): the panel scans out the picture turned R clockwise, so
//    the touch layer, glued to the panel, is turned with it. With (u, v) on the panel (native
//    top-left (0, 0), u to the right, v down) and (p, q) on the picture as the shopper sees it,
//    turning the picture R clockwise puts picture point (p, q) at panel point
//        R = 0: (p, q)   R = 90: (1 - q, p)   R = 180: (1 - p, 1 - q)   R = 270: (q, 1 - p)
//    and the mapping is the inverse:
//        R = 0: (u, v)   R = 90: (v, 1 - u)   R = 180: (1 - u, 1 - v)   R = 270: (1 - v, u).
//    Example, R = 90: the panel's native top-left corner shows the picture's bottom-left one.
// 3. Scale to the picture's size: (p, q) in [0, 1] -> (p W, q H) pixels, (0, 0) being the
//    picture's top-left corner and (W, H) its bottom-right one (continuous coordinates).

#include <array>

#include <glm/vec2.hpp>

#include "util/result.hpp"

namespace gem::kiosk {

using CalibrationMatrix = std::array<double, 6>;
inline constexpr CalibrationMatrix identity_calibration{1.0, 0.0, 0.0, 0.0, 1.0, 0.0};

class TouchMapping {
  public:
    TouchMapping() = default;  // identity on a 1x1 picture: positions stay normalised
    // rotation_deg: 0, 90, 180 or 270 (see touch_rotation_from_options for config values).
    TouchMapping(const CalibrationMatrix& calibration, int rotation_deg, glm::dvec2 picture_size);

    glm::dvec2 to_picture(glm::dvec2 normalised) const;
    // Turns a panel-normalised point into picture-normalised one (steps 1 and 2 only).
    glm::dvec2 to_picture_normalised(glm::dvec2 normalised) const;

    glm::dvec2 picture_size() const { return picture_size_; }
    int rotation_deg() const { return rotation_deg_; }

  private:
    CalibrationMatrix calibration_ = identity_calibration;
    int rotation_deg_ = 0;
    glm::dvec2 picture_size_{1.0, 1.0};
};

// InputOptions::rotation_deg as configured (-1: follow the display) -> 0, 90, 180 or 270.
Result<int> touch_rotation_from_options(int configured_deg, int display_rotation_deg);

}  // namespace gem::kiosk
