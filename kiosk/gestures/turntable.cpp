#include "gestures/turntable.hpp"

#include <cmath>
#include <numbers>

namespace gem::kiosk {

glm::dvec2 turntable_turn(glm::dvec2 drag_px, double roll_deg, double degrees_per_px) {
    // Camera::make rolls the axes: right = cos r right0 + sin r up0, up = -sin r right0 +
    // cos r up0. A drag of (sx, sy) along the rolled axes (sy upward) is then
    // (sx cos r - sy sin r) along right0 and (sx sin r + sy cos r) along up0.
    const double roll = roll_deg * std::numbers::pi / 180.0;
    const double sx = drag_px.x;
    const double sy = -drag_px.y;  // picture y grows downward
    const double along_right0 = sx * std::cos(roll) - sy * std::sin(roll);
    const double along_up0 = sx * std::sin(roll) + sy * std::cos(roll);
    return {-along_right0 * degrees_per_px, -along_up0 * degrees_per_px};
}

}  // namespace gem::kiosk
