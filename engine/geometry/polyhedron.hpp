#pragma once
// Building closed solids: a convex stone as the intersection of half-spaces, and a stone from
// a closed triangle mesh (coplanar neighbours merged into facets, convexity detected).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

// One cutting plane of a convex design: the solid is { x : plane.n·x <= plane.d }.
struct FacetPlane {
    Plane plane;
    FacetKind kind = FacetKind::other;
    std::string name;
};

// Intersects the half-spaces. Planes that end up with no area (redundant) are an error naming
// the plane, since a design whose facet vanishes is not the design asked for; so is an
// unbounded or empty intersection. The result has loops, triangles and convex = true.
Result<Stone> stone_from_planes(const std::vector<FacetPlane>& planes, std::string name);

// Builds a stone from a closed, consistently wound triangle mesh (outward = counter-clockwise).
// Welds vertices closer than `weld_tolerance` (relative to the mesh size), merges coplanar
// neighbouring triangles into facets, detects convexity. Open or non-manifold meshes are errors.
// Coplanarity and convexity are judged within `planar_tolerance` of the mesh size. Files written
// in float32 near their origin (binary STL, most exporters) carry ~6e-8 relative rounding, while
// neighbouring facets of a real cut differ by at least a fraction of a degree, so the default
// 1e-6 separates the two safely; a stone far from its file's origin needs more (gltf_piece.cpp).
inline constexpr double kPlanarRelative = 1e-6;
Result<Stone> stone_from_triangles(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                   std::string name, double weld_tolerance = 1e-9,
                                   double planar_tolerance = kPlanarRelative);

// A convex stone whose mesh is not closed (an export that lost a few triangles): the planes of
// the triangles it has, merged within `planar_tolerance` of its size, intersected. An error when
// a corner lies outside any plane (not convex: what is missing cannot be told), and when a
// whole facet is missing (the planes left would close the stone with a corner it never had).
Result<Stone> stone_closed_by_its_planes(const std::vector<glm::dvec3>& positions,
                                         const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                         std::string name, double planar_tolerance);

// Triangulates every facet loop (ear clipping, so non-convex facets work) into stone.triangles.
void triangulate_facets(Stone& stone);

}  // namespace gem
