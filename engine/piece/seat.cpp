#include "piece/seat.hpp"

#include <algorithm>

#include "piece/stone_shape.hpp"

namespace gem {

std::optional<glm::dvec3> seat_ball(const Stone& stone, const glm::dvec3& above,
                                    const glm::dvec3& down, double radius) {
    const StoneExtent e = stone_extent(stone);
    const double want = radius - kSeatMm;  // the centre's distance to the surface when seated
    // Lowered no further than the girdle's bottom; above the stone the distance only grows
    // with the height (the crown is convex), so one change of side is bisected.
    double lo = 0.0;
    double hi =
        (glm::dot(above, -down) - e.girdle_bottom) / std::max(glm::dot(-down, {0, 1, 0}), 0.05);
    if (!(signed_distance(stone, above) > want)) return std::nullopt;
    if (!(signed_distance(stone, above + hi * down) < want)) return std::nullopt;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (signed_distance(stone, above + mid * down) > want ? lo : hi) = mid;
    }
    return above + 0.5 * (lo + hi) * down;
}

}  // namespace gem
