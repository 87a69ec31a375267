#pragma once
// Triangulation of one planar polygon by ear clipping, shared by the facet builders and the
// mesh importers (a polygon face of an OBJ file need not be convex).

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

// Appends the triangles of the simple polygon `loop` (indices into `vertices`), which winds
// counter-clockwise seen from the side `normal` points to. The triangles keep that winding.
void triangulate_polygon(const std::vector<glm::dvec3>& vertices,
                         const std::vector<std::uint32_t>& loop, const glm::dvec3& normal,
                         std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace gem
