#pragma once
// The exit of a ray inside a convex stone, found by walking the facets (docs/design.md,
// "Exact exits"): the CPU twin of the trace method's shader (trace.frag).
//
// A ray inside leaves through the forward-facing plane with the smallest t. Take a candidate
// facet g, go to where the ray meets its plane, and test that point against g's edge
// neighbours only: a convex facet is its plane cut by their half-spaces. If it lies outside a
// neighbour h, the ray crossed h first (t_h < t_g, and h faces forward), so the walk moves to
// h; t falls at every step, so it ends, on the exit facet. Near an edge or a corner (within
// kTie) the candidates are ordered by (t, facet index) as the full search orders them, and
// the facets sharing only a corner with g are tested too, so the walk and the full search
// (convex_intersector.cpp) agree on every ray.
//
// The first guess: the facet through which a ray from the stone's centre in the same
// direction leaves, from a small cube map of directions made when the stone loads.

#include <cstdint>
#include <vector>

#include "geometry/facet_adjacency.hpp"
#include "geometry/stone.hpp"
#include "trace/intersector.hpp"

namespace gem {

// What a walk cost: plane evaluations (one dot product with the direction, one with the
// point) and steps from one facet to another; fell_back when it ended in the full search.
struct WalkCost {
    std::uint64_t walks = 0;
    std::uint64_t planes = 0;
    std::uint64_t steps = 0;
    std::uint64_t fell_back = 0;
    int longest = 0;  // most steps in one walk
};

class FacetWalk {
  public:
    // Texels per cube-map face side of the first-guess map.
    static constexpr int kGuessSide = 32;
    // Steps after which a walk gives up and searches every facet (never reached on a valid
    // convex stone; it bounds the work on a damaged one).
    static constexpr int kMaxSteps = 64;

    explicit FacetWalk(const Stone& stone);  // convex stones only

    // As Intersector::next_exit, starting from the guess map's facet for `direction`.
    bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                   SurfaceHit& hit, WalkCost* cost = nullptr) const;
    // Starting from `start` (any facet; one that does not face forward costs a full search).
    bool next_exit_from(const glm::dvec3& origin, const glm::dvec3& direction,
                        std::uint32_t from_facet, std::uint32_t start, SurfaceHit& hit,
                        WalkCost* cost = nullptr) const;

    std::uint32_t guess(const glm::dvec3& direction) const;
    // The guess map, as GL lays out a cube map (util/cube_faces.hpp): faces +x, −x, +y, −y,
    // +z, −z, each kGuessSide rows of kGuessSide facet indices, row 0 at t = 0.
    const std::vector<std::uint16_t>& guess_map() const { return guess_map_; }
    const FacetAdjacency& adjacency() const { return adjacency_; }

  private:
    double t_of(std::uint32_t f, const glm::dvec3& origin, double facing) const;

    std::vector<Plane> planes_;
    FacetAdjacency adjacency_;
    std::unique_ptr<Intersector> full_search_;
    std::vector<std::uint16_t> guess_map_;
    double tie_ = 0.0;
};

}  // namespace gem
