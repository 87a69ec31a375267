#include "gemmology/sky.hpp"

#include <cmath>
#include <numbers>

namespace gem {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

SkyZone SkyModel::zone(const glm::dvec3& d) const {
    // d.y is the sine of the elevation above the girdle plane and the cosine of the angle to
    // the viewing axis; comparing sines avoids an asin per ray.
    if (d.y < 0.0) return SkyZone::below;
    if (d.y >= std::cos(head_half_angle_deg * kDeg)) return SkyZone::head;
    if (d.y >= std::sin(red_green_deg * kDeg)) return SkyZone::high_sky;
    return SkyZone::low_sky;
}

double SkyModel::radiance_along(const glm::dvec3& d) const {
    const SkyZone z = zone(d);
    return z == SkyZone::low_sky || z == SkyZone::high_sky ? radiance : 0.0;
}

}  // namespace gem
