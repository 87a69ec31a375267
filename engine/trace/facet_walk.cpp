#include "trace/facet_walk.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "util/cube_faces.hpp"

namespace gem {

FacetWalk::FacetWalk(const Stone& stone)
    : adjacency_(facet_adjacency(stone)), full_search_(make_convex_intersector(stone)) {
    assert(stone.convex);
    planes_.reserve(stone.facets.size());
    for (const Facet& f : stone.facets) planes_.push_back(f.plane);
    // Plane values of points on a stone a few mm across carry ~1e-15 mm of rounding; a tie
    // is anything closer than this, relative to the stone's size.
    double radius = 1.0;
    for (const glm::dvec3& v : stone.vertices) radius = std::max(radius, glm::length(v));
    tie_ = 1e-12 * radius;
    const int side = kGuessSide;
    guess_map_.resize(static_cast<std::size_t>(6 * side * side));
    const glm::dvec3 centre(0.0);
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < side; ++t) {
            for (int s = 0; s < side; ++s) {
                SurfaceHit hit;
                const glm::dvec3 d = cube_face_direction(face, (s + 0.5) / side, (t + 0.5) / side);
                const bool found = full_search_->next_exit(centre, d, kNoFacet, hit);
                guess_map_[static_cast<std::size_t>((face * side + t) * side + s)] =
                    static_cast<std::uint16_t>(found ? hit.facet : 0);
            }
        }
    }
}

std::uint32_t FacetWalk::guess(const glm::dvec3& direction) const {
    const CubeTexel c = cube_face_texel(direction, kGuessSide);
    return guess_map_[static_cast<std::size_t>((c.face * kGuessSide + c.t) * kGuessSide + c.s)];
}

// The full search's own t (convex_intersector.cpp): the same expression, so equal values tie
// exactly as they do there.
double FacetWalk::t_of(std::uint32_t f, const glm::dvec3& origin, double facing) const {
    const double t = (planes_[f].d - glm::dot(planes_[f].n, origin)) / facing;
    return t < 0.0 ? 0.0 : t;
}

bool FacetWalk::next_exit(const glm::dvec3& origin, const glm::dvec3& direction,
                          std::uint32_t from_facet, SurfaceHit& hit, WalkCost* cost) const {
    return next_exit_from(origin, direction, from_facet, guess(direction), hit, cost);
}

bool FacetWalk::next_exit_from(const glm::dvec3& origin, const glm::dvec3& direction,
                               std::uint32_t from_facet, std::uint32_t start, SurfaceHit& hit,
                               WalkCost* cost) const {
    WalkCost local;
    WalkCost& c = cost != nullptr ? *cost : local;
    ++c.walks;
    auto search_everything = [&] {
        ++c.fell_back;
        c.planes += planes_.size();
        return full_search_->next_exit(origin, direction, from_facet, hit);
    };
    std::uint32_t g = start;
    if (g >= planes_.size() || g == from_facet) return search_everything();
    double facing_g = glm::dot(planes_[g].n, direction);
    ++c.planes;
    if (facing_g <= 0.0) return search_everything();

    for (int step = 0; step <= kMaxSteps; ++step) {
        const double t_g = t_of(g, origin, facing_g);
        const glm::dvec3 p = origin + t_g * direction;
        // The neighbour crossed first among those the point lies outside of.
        std::uint32_t next = kNoFacet;
        double t_next = std::numeric_limits<double>::infinity();
        double facing_next = 0.0;
        const std::uint32_t* edges = adjacency_.edges_of(g);
        const std::uint32_t* corners = adjacency_.vertices_of(g);
        const std::uint32_t n_edges = adjacency_.edge_count[g];
        const std::uint32_t n_all = n_edges + adjacency_.vertex_count[g];
        // Edge neighbours decide the walk; corner neighbours are looked at only once the
        // point is on g, to settle ties (and, by rounding, a point just outside one).
        auto scan = [&](std::uint32_t begin, std::uint32_t end, bool ties) {
            for (std::uint32_t i = begin; i < end; ++i) {
                const std::uint32_t h = i < n_edges ? edges[i] : corners[i - n_edges];
                if (h == from_facet) continue;
                ++c.planes;
                const double facing = glm::dot(planes_[h].n, direction);
                if (facing <= 0.0) continue;
                const double outside = planes_[h].signed_distance(p);
                if (outside < -tie_ || (!ties && outside <= tie_)) continue;
                const double t_h = t_of(h, origin, facing);
                if (t_h < t_next || (t_h == t_next && h < next)) {
                    next = h;
                    t_next = t_h;
                    facing_next = facing;
                }
            }
        };
        scan(0, n_edges, false);
        if (next == kNoFacet) {
            // On g: g or a facet through the same edge or corner, as the full search orders
            // them.
            next = g;
            t_next = t_g;
            facing_next = facing_g;
            scan(0, n_all, true);
            if (next == g) {
                c.longest = std::max(c.longest, step);
                hit.t = t_g;
                hit.point = p;
                hit.facet = g;
                return true;
            }
            if (t_next == t_g) {
                // A tie settled by index: the same point, a lower-numbered facet.
                c.longest = std::max(c.longest, step);
                hit.t = t_next;
                hit.point = origin + t_next * direction;
                hit.facet = next;
                return true;
            }
        }
        ++c.steps;
        g = next;
        facing_g = facing_next;
    }
    return search_everything();
}

}  // namespace gem
