#pragma once
// Which directions a scene is looked at from, relative to a database's stored views: ON a
// stored direction (the stored view nearest the scene's target, in the target's symmetric
// copy), BETWEEN stored directions (the direction near the target farthest from every stored
// view), and a PATH from a stored view toward its nearest neighbour, past the midpoint.

#include <vector>

#include <glm/glm.hpp>

#include "gemdb/view_grid.hpp"

namespace gem::accuracy {

double angle_deg(const glm::dvec3& a, const glm::dvec3& b);

// The stored direction nearest `target`, expressed near `target` (g⁻¹ · stored).
glm::dvec3 on_view(const ViewGrid& grid, const glm::dvec3& target);
// Within one spacing of `target`, the direction whose nearest stored view is farthest.
glm::dvec3 between_view(const ViewGrid& grid, const glm::dvec3& target);
// `count` directions from the stored view nearest `target` toward the nearest image of
// another stored view, at fractions 0 .. `beyond` (> 0.5) of the way.
std::vector<glm::dvec3> view_path(const ViewGrid& grid, const glm::dvec3& target, int count,
                                  double beyond);

}  // namespace gem::accuracy
