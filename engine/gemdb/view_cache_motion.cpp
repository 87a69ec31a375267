#include "gemdb/view_cache_motion.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

namespace {

// Rodrigues' rotation formula: v turned by `angle` about unit `axis` (right-handed).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

}  // namespace

std::vector<std::uint32_t> views_ahead(const ViewGrid& grid, const glm::dvec3& direction,
                                       const glm::dvec3& angular_velocity, double horizon_s,
                                       std::uint32_t max_views) {
    std::vector<std::uint32_t> ahead;
    const double speed = glm::length(angular_velocity);
    if (!(speed > 0.0) || !(horizon_s > 0.0) || max_views == 0) return ahead;
    const glm::dvec3 axis = angular_velocity / speed;
    const glm::dvec3 start = glm::normalize(direction);
    const std::uint32_t here = grid.nearest(start).view;
    // Half a grid spacing per step cannot jump over a view's cell; the cap bounds a wild
    // velocity (the path then wraps the sphere and stops at max_views anyway).
    const double arc = std::min(speed * horizon_s, 2.0 * 3.141592653589793);
    const double step = grid.spec().spacing_rad / 2.0;
    const int steps = std::clamp(static_cast<int>(std::ceil(arc / step)), 1, 1024);
    for (int i = 1; i <= steps && ahead.size() < max_views; ++i) {
        const std::uint32_t view = grid.nearest(rotate(start, axis, arc * i / steps)).view;
        if (view != here && std::find(ahead.begin(), ahead.end(), view) == ahead.end()) {
            ahead.push_back(view);
        }
    }
    return ahead;
}

ViewMatch nearest_image(const ViewGrid& grid, std::uint32_t view, const glm::dvec3& asked) {
    const glm::dvec3& stored = grid.direction(view);
    ViewMatch best{view, 0, 4.0};
    for (std::size_t g = 0; g < grid.group().size(); ++g) {
        const double cosine = std::clamp(glm::dot(grid.group()[g] * asked, stored), -1.0, 1.0);
        const double angle = std::acos(cosine);
        if (angle < best.angle) best = {view, static_cast<std::uint32_t>(g), angle};
    }
    return best;
}

}  // namespace gem
