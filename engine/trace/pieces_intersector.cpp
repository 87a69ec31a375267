// A non-convex stone traced as its convex pieces (trace/convex_pieces.hpp): the CPU twin of the
// trace shader's PIECES search, which the tests hold against the triangle BVH.

#include <algorithm>
#include <cassert>
#include <limits>
#include <vector>

#include "geometry/stone.hpp"
#include "trace/convex_pieces.hpp"
#include "trace/intersector.hpp"

namespace gem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A plane bounding a piece: a facet, or a cut (kNoFacet) the ray passes through unchanged.
struct Bound {
    Plane plane;
    std::uint32_t facet = kNoFacet;
};

class PiecesIntersector final : public Intersector {
  public:
    PiecesIntersector(const Stone& stone, ConvexPieces pieces)
        : stone_(stone),
          pieces_(std::move(pieces)),
          on_cut_(1e-9 * bounding_radius(stone.vertices)) {
        for (const ConvexPieces::Piece& piece : pieces_.pieces()) {
            std::vector<Bound> bounds;
            for (std::uint32_t f : piece.facets) bounds.push_back({stone.facets[f].plane, f});
            for (const Plane& cut : piece.cuts) bounds.push_back({cut, kNoFacet});
            bounds_.push_back(std::move(bounds));
        }
    }

    // From a facet of the stone (trace.frag's way): only a ray leaving through a pocket wall
    // can come back, and only onto a pocket wall. From elsewhere: the nearest of the pieces'
    // entries, each by the slab method, one through a cut not counting (the piece beyond the
    // cut gives the ray's earlier one).
    bool next_entry(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                    SurfaceHit& hit) const override {
        const auto& walls = pieces_.pocket_walls();
        if (from_facet != kNoFacet) {
            if (std::find(walls.begin(), walls.end(), from_facet) == walls.end()) return false;
            return wall_entry(origin, direction, from_facet, hit);
        }
        double best = kInf;
        std::uint32_t entry_facet = kNoFacet;
        for (const std::vector<Bound>& bounds : bounds_) {
            double t_in = -kInf;
            double t_out = kInf;
            const Bound* entry = nullptr;
            bool missed = false;
            for (const Bound& b : bounds) {
                const double facing = glm::dot(b.plane.n, direction);
                const double inside_by = b.plane.d - glm::dot(b.plane.n, origin);
                if (facing < 0.0 && inside_by / facing > t_in) {
                    t_in = inside_by / facing;
                    entry = &b;
                } else if (facing > 0.0) {
                    t_out = std::min(t_out, inside_by / facing);
                } else if (facing == 0.0 && inside_by < 0.0) {
                    missed = true;
                }
            }
            if (missed || entry == nullptr || entry->facet == kNoFacet || t_in < 0.0 ||
                t_out <= t_in || t_in >= best) {
                continue;
            }
            best = t_in;
            entry_facet = entry->facet;
        }
        if (entry_facet == kNoFacet) return false;
        hit.t = best;
        hit.point = origin + best * direction;
        hit.facet = entry_facet;
        return true;
    }

    // The nearest plane ahead in the piece holding the origin; through a cut, on in the piece
    // beyond. Each crossing enters a piece further along the ray, so there are fewer crossings
    // than pieces.
    bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                   SurfaceHit& hit) const override {
        int piece = pieces_.locate(origin, direction, on_cut_);
        for (std::size_t crossing = 0; crossing < bounds_.size(); ++crossing) {
            double t_best = kInf;
            const Bound* exit = nullptr;
            for (const Bound& b : bounds_[static_cast<std::size_t>(piece)]) {
                if (b.facet != kNoFacet && b.facet == from_facet) continue;
                const double facing = glm::dot(b.plane.n, direction);
                if (facing <= 0.0) continue;
                const double t = std::max((b.plane.d - glm::dot(b.plane.n, origin)) / facing, 0.0);
                if (t < t_best) {
                    t_best = t;
                    exit = &b;
                }
            }
            if (exit == nullptr) return false;
            if (exit->facet != kNoFacet) {
                hit.t = t_best;
                hit.point = origin + t_best * direction;
                hit.facet = exit->facet;
                return true;
            }
            piece = pieces_.locate(origin + t_best * direction, direction, on_cut_);
        }
        return false;
    }

    bool can_reenter() const override { return true; }

  private:
    // The nearest pocket-wall polygon the ray meets from outside, leaving `from_facet`.
    bool wall_entry(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                    SurfaceHit& hit) const {
        double best = kInf;
        std::uint32_t entry_facet = kNoFacet;
        for (const ConvexPieces::WallPolygon& wall : pieces_.wall_polygons()) {
            const Plane& plane = stone_.facets[wall.facet].plane;
            const double facing = glm::dot(plane.n, direction);
            if (wall.facet == from_facet || facing >= 0.0) continue;
            const double t = (plane.d - glm::dot(plane.n, origin)) / facing;
            if (t < -on_cut_ || t >= best) continue;
            const glm::dvec3 p = origin + t * direction;
            bool inside = true;
            for (const Plane& edge : wall.edges)
                inside = inside && edge.signed_distance(p) <= on_cut_;
            if (!inside) continue;
            best = t;
            entry_facet = wall.facet;
        }
        if (entry_facet == kNoFacet) return false;
        hit.t = std::max(best, 0.0);
        hit.point = origin + hit.t * direction;
        hit.facet = entry_facet;
        return true;
    }

    const Stone& stone_;
    ConvexPieces pieces_;
    double on_cut_;
    std::vector<std::vector<Bound>> bounds_;  // per piece
};

}  // namespace

std::unique_ptr<Intersector> make_pieces_intersector(const Stone& stone, ConvexPieces pieces) {
    return std::make_unique<PiecesIntersector>(stone, std::move(pieces));
}

}  // namespace gem
