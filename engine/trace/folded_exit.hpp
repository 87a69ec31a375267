#pragma once
// The exit of a ray inside a convex stone with mirror symmetry about its axis (y), found among
// a few planes by folding the ray into one wedge of the symmetry: the CPU twin of the trace
// shader's EXIT_FOLDED search (trace.frag), beside the facet walk (trace/facet_walk.hpp).
//
// Why: a SIMD rasteriser runs every instruction for all its lanes, so the exit search costs
// the same for every pixel whatever the ray does. Testing every plane costs ~13 operations
// per facet and bounce (89 facets on a brilliant); a walk reads scattered planes per lane.
// Folding keeps the planes as constants and tests a tenth of them, in one round or two.
//
// How: a stone whose facet planes are mirrored onto each other by the planes x = 0 and z = 0
// and by the mirrors at azimuths 45°, 22.5°, 11.25° (C2v, C4v, C8v, C16v about y) looks the
// same from every wedge between neighbouring mirrors. Fold a point into the first wedge
// (|x|, |z|, then a reflection across each smaller mirror it lies beyond); the same
// reflections, applied to a ray, make the stone's wedge around that point the first wedge.
// There only the facets that reach inside the first wedge can hold the point (a facet that
// only touches a mirror line is matched there by its image from inside), so a ray's exit,
// when it lies in that wedge, is found among those planes alone: 8 of the brilliant's 89.
//
// The search: fold the ray by the wedge of a first guess (where the ray leaves the stone's
// outline turned about its axis: a pavilion cone, a crown cone, the girdle's cylinder, the
// table's plane; see TurnedOutline), take the nearest forward plane among the wedge's
// facets, and check that the point lies in the wedge. If it does, it is the exit: the point
// is inside every plane of the facets that bound the stone in that wedge, so inside the
// stone, and on its surface; a ray from inside meets the surface once. If not, fold by the
// point's own wedge and take the nearest plane over all wedges seen so far; a point in a
// wedge already seen is the exit for the same reason. Each round sees a new wedge, so the
// search ends, at the latest when it has seen every plane. The guess only saves rounds: any
// guess gives the same exit.
//
// The facet a ray starts on faces away from it (it was refracted or reflected inward), so
// forward means n·d > kFacingMin, not an index test: the fold changes facet indices.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/stone.hpp"
#include "trace/intersector.hpp"

namespace gem {

// The first guess's solid: the stone turned about its axis, with z scaled by z_scale so that
// an elongated stone's outline is about round. Points p with r = |(p.x, p.z z_scale)|:
// r <= radius (the girdle), r <= pavilion_slope (y - y_min) (a cone from the culet through
// the girdle's lower edge), r <= crown_slope (crown_apex - y) (a cone through the girdle's
// upper edge and the table's), and y_min <= y <= y_max. A slope of 0 leaves its cone out.
struct TurnedOutline {
    double z_scale = 1.0;
    double radius = 1.0;
    double y_min = 0.0;
    double y_max = 0.0;
    double pavilion_slope = 0.0;
    double crown_slope = 0.0;
    double crown_apex = 0.0;
};

struct FoldCost {
    std::uint64_t searches = 0;
    std::uint64_t rounds = 0;  // wedges folded into
    std::uint64_t planes = 0;  // planes tested
    int most_rounds = 0;
};

class FoldedExit {
  public:
    // Mirrors folded by, after |x| and |z|: up to three (45°, 22.5°, 11.25°).
    static constexpr int kMaxLevels = 3;
    // n·d above which a plane faces the ray forward (see above).
    static constexpr double kFacingMin = 1e-6;
    // How far inside a wedge's edges (a share of the stone's radius) a point must lie to be
    // taken as the exit in that round. Within a float's rounding of a mirror line the facet
    // beyond it ties with its image inside; a point that close takes a round in the wedge
    // beyond too, so both are tested and the nearer plane wins, as in the full search.
    static constexpr double kInside = 1e-5;

    // The fold of a convex stone, or nothing when its planes are not mirrored onto each other
    // by at least x = 0 and z = 0.
    static std::optional<FoldedExit> make(const Stone& stone);

    // As Intersector::next_exit (from_facet is not needed: see above).
    bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction, SurfaceHit& hit,
                   FoldCost* cost = nullptr) const;

    // What the shader is built from.
    int levels() const { return levels_; }
    int wedges() const { return 4 << levels_; }
    // Unit normals (x, z) of the mirror lines folded across, pointing beyond them.
    const std::vector<glm::dvec2>& mirrors() const { return mirrors_; }
    // The first wedge: points p with dot(edge, p.xz) >= 0 for both edges; a round's point is
    // taken when both are at least inside() (mm).
    const std::array<glm::dvec2, 2>& wedge_edges() const { return edges_; }
    double inside() const { return inside_; }
    // The facets reaching inside the first wedge (indices into stone.facets).
    const std::vector<std::uint32_t>& candidates() const { return candidates_; }
    // The first guess's solid.
    const TurnedOutline& outline() const { return outline_; }

    // The fold of a point's wedge as bits (bit 0: x negated, bit 1: z negated, bit 2 + i:
    // reflected across mirror i), and a vector folded or unfolded by such bits.
    std::uint32_t fold_bits(glm::dvec2 xz) const;
    glm::dvec3 fold(glm::dvec3 v, std::uint32_t bits) const;
    glm::dvec3 unfold(glm::dvec3 v, std::uint32_t bits) const;
    // Where the ray leaves the first guess's solid.
    glm::dvec3 guess(const glm::dvec3& origin, const glm::dvec3& direction) const;

  private:
    FoldedExit() = default;
    std::vector<Plane> planes_;
    int levels_ = 0;
    std::vector<glm::dvec2> mirrors_;
    std::array<glm::dvec2, 2> edges_{};
    double inside_ = 0.0;
    std::vector<std::uint32_t> candidates_;
    // The facet that candidate c becomes when unfolded by bits: [bits * candidates + c].
    std::vector<std::uint32_t> unfolded_facet_;
    TurnedOutline outline_;
};

}  // namespace gem
