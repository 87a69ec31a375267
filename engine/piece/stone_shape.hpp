#pragma once
// What a setting needs to know of a stone's shape, in the stone's own frame: its size, how
// far its outline reaches, and how far a point is from its surface. Used to seat metal on a
// stone and to check pieces; none of it is on a per-frame path.

#include <glm/glm.hpp>

#include "geometry/stone.hpp"

namespace gem {

// The stone scaled about its centre (vertices and facet planes; the symmetry is unchanged).
Stone scaled_stone(Stone stone, double factor);

struct StoneExtent {
    double girdle_radius = 0.0;  // the largest distance of the outline from the y axis
    double girdle_top = 0.0;     // the top of the girdle band, where the crown begins
    double girdle_bottom = 0.0;  // its bottom, where the pavilion begins (negative)
    double table_y = 0.0;        // the highest point
    double culet_y = 0.0;        // the lowest point (negative)
};
StoneExtent stone_extent(const Stone& stone);

// The girdle's width as a jeweller measures it: the short side of its outline.
double girdle_width(const Stone& stone);
// The stone scaled to girdle width `width_mm`, as a piece sizes the stones it names (and
// gemtables builds a piece's stone's tables: the same stone to the last bit).
Stone stone_at_width(Stone stone, double width_mm);

// How far the outline reaches from the centre along horizontal direction `u` (unit, y = 0):
// the farthest crossing of that ray with the surface, so a non-convex outline counts too.
double outline_radius(const Stone& stone, const glm::dvec3& u);

// The point of triangle abc nearest to p.
glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                               const glm::dvec3& c);

// The point of the stone's surface nearest to p (on one of its triangles).
glm::dvec3 closest_point(const Stone& stone, const glm::dvec3& p);

// The distance from p to the stone's surface, negative inside (the closest point on any of its
// triangles; inside is decided by the facet planes for a convex stone, by crossings otherwise).
double signed_distance(const Stone& stone, const glm::dvec3& p);

}  // namespace gem
