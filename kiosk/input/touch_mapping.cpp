#include "input/touch_mapping.hpp"

#include <cassert>
#include <string>

namespace gem::kiosk {

TouchMapping::TouchMapping(const CalibrationMatrix& calibration, int rotation_deg,
                           glm::dvec2 picture_size)
    : calibration_(calibration), rotation_deg_(rotation_deg), picture_size_(picture_size) {
    assert(rotation_deg == 0 || rotation_deg == 90 || rotation_deg == 180 || rotation_deg == 270);
}

glm::dvec2 TouchMapping::to_picture_normalised(glm::dvec2 normalised) const {
    const CalibrationMatrix& m = calibration_;
    const double u = m[0] * normalised.x + m[1] * normalised.y + m[2];
    const double v = m[3] * normalised.x + m[4] * normalised.y + m[5];
    switch (rotation_deg_) {
        case 90:
            return {v, 1.0 - u};
        case 180:
            return {1.0 - u, 1.0 - v};
        case 270:
            return {1.0 - v, u};
        default:
            return {u, v};
    }
}

glm::dvec2 TouchMapping::to_picture(glm::dvec2 normalised) const {
    return to_picture_normalised(normalised) * picture_size_;
}

Result<int> touch_rotation_from_options(int configured_deg, int display_rotation_deg) {
    const int deg = configured_deg == -1 ? display_rotation_deg : configured_deg;
    const int turned = ((deg % 360) + 360) % 360;
    if (turned % 90 != 0) {
        return Error{"input rotation_deg: " + std::to_string(deg) +
                     " is not 0, 90, 180 or 270 (or -1 for the display's)"};
    }
    return turned;
}

}  // namespace gem::kiosk
