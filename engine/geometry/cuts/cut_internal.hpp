#pragma once
// Private to the cut builders: girdle outlines, the brilliant facet pattern, symmetry groups.

#include <functional>
#include <vector>

#include "geometry/cuts.hpp"
#include "geometry/polyhedron.hpp"

namespace gem::cuts {

// A point of a girdle outline in the girdle plane, as (x, z), with its outward unit normal.
// At a pointed tip the normal is the bisector of the two sides' normals.
struct OutlinePoint {
    glm::dvec2 p;
    glm::dvec2 n;
};

// A closed convex girdle outline as a function of a parameter t in [0, 2π), counter-clockwise
// from +x toward +z. The brilliant pattern puts its 8 main facets at t = k·45°.
using Outline = std::function<OutlinePoint(double t)>;

Outline round_outline(double radius);
Outline oval_outline(double length, double width);
Outline marquise_outline(double length, double width);
Outline pear_outline(double length, double width);
Outline cushion_outline(double length, double width);
Outline princess_outline(double length, double width);

// The 57/58-facet brilliant pattern (see brilliant.cpp) on a convex outline, with vertical
// girdle planes through chords between `girdle_samples` outline points (a multiple of 16).
// The table's corners are the points of `table_outline` (default: the girdle outline) at the
// main facets' parameters, scaled by table_pct.
std::vector<FacetPlane> brilliant_planes(const Outline& outline, int girdle_samples,
                                         const CutParams& params,
                                         const Outline* table_outline = nullptr);

// Heights of the brilliant pattern's levels: girdle thickness g (the girdle spans ±g/2 at the
// main facets), the table plane and the culet point (see brilliant.cpp).
struct BrilliantLevels {
    double girdle;
    double table_y;
    double culet_y;
};
BrilliantLevels brilliant_levels(const CutParams& params);

// The plane containing girdle point `g` and `apex` whose normal's horizontal part is along the
// outline normal `n` (x, z); `up` is +1 for the crown, −1 for the pavilion.
Plane tilted_plane(const glm::dvec3& g, const glm::dvec3& apex, const glm::dvec2& n, double up);

// Vertical girdle planes through the chords of a closed outline polygon; consecutive
// collinear chords (a princess' straight sides) share one plane.
std::vector<FacetPlane> girdle_planes(const std::vector<OutlinePoint>& polygon);

// The plane through three points, its normal turned to point away from `inside`.
Plane plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                    const glm::dvec3& inside);

// Point groups as matrices, identity first. C_nv: n rotations about y and n vertical mirrors,
// the first mirror containing the x axis.
std::vector<glm::dmat3> cnv_group(int n);
std::vector<glm::dmat3> mirror_group(const glm::dvec3& mirror_normal);

// The planes of `planes` that make a facet of their intersection, in order; for shapes made
// by cutting a pattern (the heart's halves), where some of the pattern's facets vanish.
// Defined with stone_from_planes in polyhedron.cpp, whose clipping it shares.
Result<std::vector<FacetPlane>> planes_that_make_facets(const std::vector<FacetPlane>& planes);

Result<Stone> make_emerald(const CutParams& params);
Result<Stone> make_heart(const CutParams& params);

}  // namespace gem::cuts
