#pragma once
// Planar polygons given as loops of corner indices: their area vector, and their triangulation
// by ear clipping, shared by the facet builders, the mesh importers (a polygon face of an OBJ
// file need not be convex) and the mesh repairs.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

// Newell's sum over the loop: twice its vector area, along the side from which it winds
// counter-clockwise.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& vertices,
                         const std::vector<std::uint32_t>& loop);
// The loop's area (0 for fewer than three corners).
inline double loop_area(const std::vector<glm::dvec3>& vertices,
                        const std::vector<std::uint32_t>& loop) {
    return loop.size() < 3 ? 0.0 : 0.5 * glm::length(newell_normal(vertices, loop));
}

// Appends the triangles of the simple polygon `loop` (indices into `vertices`), which winds
// counter-clockwise seen from the side `normal` points to. The triangles keep that winding.
void triangulate_polygon(const std::vector<glm::dvec3>& vertices,
                         const std::vector<std::uint32_t>& loop, const glm::dvec3& normal,
                         std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace gem
