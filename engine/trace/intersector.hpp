#pragma once
// Where a ray next crosses a stone's surface. Three implementations: half-space clipping for
// convex stones (convex_intersector), a triangle BVH for any closed mesh (bvh_intersector) and
// a non-convex stone's convex pieces (pieces_intersector, the trace shader's twin).
// Private to the tracer, its tests and benchmarks.

#include <cstdint>
#include <limits>
#include <memory>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "trace/convex_pieces.hpp"

namespace gem {

inline constexpr std::uint32_t kNoFacet = std::numeric_limits<std::uint32_t>::max();

struct SurfaceHit {
    double t = 0.0;         // distance along the (unit) direction
    glm::dvec3 point{0.0};  // origin + t · direction
    std::uint32_t facet = kNoFacet;
};

class Intersector {
  public:
    virtual ~Intersector() = default;

    // The nearest point where the ray crosses the surface from outside to inside (the facet
    // faces the ray: n·d < 0). `from_facet` is the facet the ray starts on, or kNoFacet.
    virtual bool next_entry(const glm::dvec3& origin, const glm::dvec3& direction,
                            std::uint32_t from_facet, SurfaceHit& hit) const = 0;

    // The nearest point where a ray inside the stone (or starting on its surface, going
    // inward) leaves it (n·d > 0). False only if the solid is not closed or the ray is not
    // inside: the tracer treats that as a bug.
    virtual bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction,
                           std::uint32_t from_facet, SurfaceHit& hit) const = 0;

    // False for convex stones: a ray that has left one cannot meet it again.
    virtual bool can_reenter() const = 0;
};

// Chooses by stone.convex. The stone must outlive the intersector.
std::unique_ptr<Intersector> make_intersector(const Stone& stone);
std::unique_ptr<Intersector> make_convex_intersector(const Stone& stone);
std::unique_ptr<Intersector> make_bvh_intersector(const Stone& stone);
std::unique_ptr<Intersector> make_pieces_intersector(const Stone& stone, ConvexPieces pieces);

}  // namespace gem
