// Convex stones: the solid is the intersection of the facets' half-spaces n·x <= d, so a ray
// is clipped against every plane (the slab method generalised to arbitrary planes). Entry is
// the last plane the ray crosses going in, exit the first it crosses going out. Nothing is
// tessellated, so there are no cracks between facets: a ray through an edge or a vertex is
// clipped by the same planes from both sides and cannot slip through.

#include <cassert>
#include <limits>
#include <vector>

#include "trace/intersector.hpp"

namespace gem {
namespace {

class ConvexIntersector final : public Intersector {
  public:
    explicit ConvexIntersector(const Stone& stone) {
        assert(!stone.facets.empty());
        planes_.reserve(stone.facets.size());
        for (const Facet& facet : stone.facets) planes_.push_back(facet.plane);
    }

    bool next_entry(const glm::dvec3& origin, const glm::dvec3& direction,
                    std::uint32_t /*from_facet*/, SurfaceHit& hit) const override {
        double t_in = -std::numeric_limits<double>::infinity();
        double t_out = std::numeric_limits<double>::infinity();
        std::uint32_t entry = kNoFacet;
        for (std::uint32_t i = 0; i < planes_.size(); ++i) {
            const double facing = glm::dot(planes_[i].n, direction);
            const double inside_by = planes_[i].d - glm::dot(planes_[i].n, origin);
            if (facing < 0.0) {
                const double t = inside_by / facing;
                if (t > t_in) {
                    t_in = t;
                    entry = i;
                }
            } else if (facing > 0.0) {
                const double t = inside_by / facing;
                if (t < t_out) t_out = t;
            } else if (inside_by < 0.0) {
                return false;  // parallel to a plane and outside it
            }
        }
        // t_in < 0: the origin is inside, so there is no entry ahead of it.
        if (entry == kNoFacet || t_in > t_out || t_in < 0.0) return false;
        hit.t = t_in;
        hit.point = origin + t_in * direction;
        hit.facet = entry;
        return true;
    }

    bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                   SurfaceHit& hit) const override {
        double t_best = std::numeric_limits<double>::infinity();
        std::uint32_t exit = kNoFacet;
        for (std::uint32_t i = 0; i < planes_.size(); ++i) {
            if (i == from_facet) continue;
            const double facing = glm::dot(planes_[i].n, direction);
            if (facing <= 0.0) continue;
            // A start point a rounding error outside a plane gives a tiny negative t; it
            // leaves through that plane right where it is.
            double t = (planes_[i].d - glm::dot(planes_[i].n, origin)) / facing;
            if (t < 0.0) t = 0.0;
            if (t < t_best) {
                t_best = t;
                exit = i;
            }
        }
        if (exit == kNoFacet) return false;
        hit.t = t_best;
        hit.point = origin + t_best * direction;
        hit.facet = exit;
        return true;
    }

    bool can_reenter() const override { return false; }

  private:
    std::vector<Plane> planes_;
};

}  // namespace

std::unique_ptr<Intersector> make_convex_intersector(const Stone& stone) {
    return std::make_unique<ConvexIntersector>(stone);
}

std::unique_ptr<Intersector> make_intersector(const Stone& stone) {
    return stone.convex ? make_convex_intersector(stone) : make_bvh_intersector(stone);
}

}  // namespace gem
