#pragma once
// Geometry the view cache needs beyond ViewGrid's lookups: which stored views a turning
// camera will pass, and how close an asked direction comes to one given stored view.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/view_grid.hpp"

namespace gem {

// The distinct stored views nearest to the directions `direction` passes while it turns with
// `angular_velocity` (axis × rad/s) for `horizon_s` seconds, in the order it meets them, the
// view nearest to `direction` itself left out; at most `max_views`.
std::vector<std::uint32_t> views_ahead(const ViewGrid& grid, const glm::dvec3& direction,
                                       const glm::dvec3& angular_velocity, double horizon_s,
                                       std::uint32_t max_views);

// The symmetric image g · asked closest to stored view `view` (asked is unit length).
ViewMatch nearest_image(const ViewGrid& grid, std::uint32_t view, const glm::dvec3& asked);

}  // namespace gem
