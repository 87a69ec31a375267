#include "trace/convex_pieces.hpp"

#include <cmath>
#include <cstddef>

#include "geometry/stone.hpp"

namespace gem {
namespace {

constexpr std::size_t kMaxCandidates = 16;

// A region of space: the intersection of half-spaces n·x <= d.
using Region = std::vector<Plane>;

// The part of a facet's polygon inside half-space h (Sutherland-Hodgman, one plane). A
// polygon lying in h's plane (within `tol`) is kept when the facet faces out of h's side, as
// h's own boundary does: the solid is then on h's inner side.
std::vector<glm::dvec3> clip(const std::vector<glm::dvec3>& polygon, const Plane& h,
                             const glm::dvec3& facet_normal, double tol) {
    bool on_plane = true;
    for (const glm::dvec3& p : polygon)
        on_plane = on_plane && std::abs(h.signed_distance(p)) <= tol;
    if (on_plane) return glm::dot(facet_normal, h.n) > 0.0 ? polygon : std::vector<glm::dvec3>{};
    std::vector<glm::dvec3> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = h.signed_distance(a);
        const double db = h.signed_distance(b);
        if (da <= 0.0) kept.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
            kept.push_back(a + (da / (da - db)) * (b - a));
        }
    }
    return kept;
}

double area(const std::vector<glm::dvec3>& polygon) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        sum += glm::cross(polygon[i], polygon[(i + 1) % polygon.size()]);
    }
    return 0.5 * glm::length(sum);
}

// The stone cut to a region: the facets with area inside it and the corners of the piece.
struct Cut {
    std::vector<std::uint32_t> facets;
    std::vector<glm::dvec3> corners;
};

Cut cut_to(const Stone& stone, const Region& region, double tol) {
    Cut cut;
    for (std::uint32_t f = 0; f < stone.facets.size(); ++f) {
        std::vector<glm::dvec3> polygon;
        for (std::uint32_t v : stone.facets[f].loop) polygon.push_back(stone.vertices[v]);
        for (const Plane& h : region) polygon = clip(polygon, h, stone.facets[f].plane.n, tol);
        if (polygon.size() < 3 || area(polygon) <= tol * tol) continue;
        cut.facets.push_back(f);
        cut.corners.insert(cut.corners.end(), polygon.begin(), polygon.end());
    }
    return cut;
}

bool convex(const Stone& stone, const Cut& cut, double tol) {
    for (std::uint32_t f : cut.facets) {
        for (const glm::dvec3& c : cut.corners) {
            if (stone.facets[f].plane.signed_distance(c) > tol) return false;
        }
    }
    return true;
}

// A partition of a region: nodes and pieces indexed from 0, the root being node 0, or the
// only piece when there are no nodes.
struct Partition {
    std::vector<ConvexPieces::Node> nodes;
    std::vector<ConvexPieces::Piece> pieces;

    int root() const { return nodes.empty() ? -1 : 0; }
    // Over all pieces: what the search costs.
    std::size_t planes() const {
        std::size_t n = 0;
        for (const ConvexPieces::Piece& p : pieces) n += p.facets.size() + p.cuts.size();
        return n;
    }
};

// Appends `part` to `into`, returning the child reference of its root.
int append(Partition& into, const Partition& part) {
    const int node_base = static_cast<int>(into.nodes.size());
    const int piece_base = static_cast<int>(into.pieces.size());
    auto shift = [&](int child) { return child >= 0 ? child + node_base : child - piece_base; };
    for (ConvexPieces::Node n : part.nodes) {
        n.below = shift(n.below);
        n.above = shift(n.above);
        into.nodes.push_back(n);
    }
    into.pieces.insert(into.pieces.end(), part.pieces.begin(), part.pieces.end());
    return shift(part.root());
}

class Splitter {
  public:
    Splitter(const Stone& stone, std::vector<Plane> candidates, double tol)
        : stone_(stone), candidates_(std::move(candidates)), tol_(tol) {}

    // The partition of `region` into fewest convex pieces, at most `budget`.
    std::optional<Partition> best(const Region& region, int budget) const {
        const Cut cut = cut_to(stone_, region, tol_);
        if (cut.facets.empty()) return std::nullopt;
        if (convex(stone_, cut, tol_))
            return Partition{{}, {{cut.facets, bounding_cuts(region, cut)}}};
        std::optional<Partition> found;
        for (const Plane& c : candidates_) {
            if (budget < 2) break;
            if (!cuts_through(cut, c)) continue;
            Region below = region;
            below.push_back(c);
            Region above = region;
            above.push_back(Plane{-c.n, -c.d});
            auto low = best(below, budget - 1);
            if (!low) continue;
            auto high = best(above, budget - static_cast<int>(low->pieces.size()));
            if (!high) continue;
            Partition p;
            p.nodes.push_back({c, 0, 0});
            p.nodes[0].below = append(p, *low);
            p.nodes[0].above = append(p, *high);
            const bool fewer =
                !found || p.pieces.size() < found->pieces.size() ||
                (p.pieces.size() == found->pieces.size() && p.planes() < found->planes());
            if (fewer) {
                found = std::move(p);
                budget = static_cast<int>(found->pieces.size()) - 1;  // only fewer pieces now
                if (found->pieces.size() == 2) break;                 // none fewer exist
            }
        }
        return found;
    }

  private:
    bool cuts_through(const Cut& cut, const Plane& c) const {
        bool below = false;
        bool above = false;
        for (const glm::dvec3& p : cut.corners) {
            const double s = c.signed_distance(p);
            below = below || s < -tol_;
            above = above || s > tol_;
        }
        return below && above;
    }

    // The region's planes that bound the piece: three corners or more on them.
    std::vector<Plane> bounding_cuts(const Region& region, const Cut& cut) const {
        std::vector<Plane> cuts;
        for (const Plane& h : region) {
            int on = 0;
            for (const glm::dvec3& p : cut.corners) on += std::abs(h.signed_distance(p)) <= tol_;
            if (on >= 3) cuts.push_back(h);
        }
        return cuts;
    }

    const Stone& stone_;
    std::vector<Plane> candidates_;
    double tol_;
};

// The facets with a corner of the stone outside their plane: off its convex hull.
std::vector<std::uint32_t> walls_of_pockets(const Stone& stone, double tol) {
    std::vector<std::uint32_t> walls;
    for (std::uint32_t f = 0; f < stone.facets.size(); ++f) {
        for (const glm::dvec3& v : stone.vertices) {
            if (stone.facets[f].plane.signed_distance(v) > tol) {
                walls.push_back(f);
                break;
            }
        }
    }
    return walls;
}

// Edge planes of the polygon `corners` (counter-clockwise seen from outside the facet with
// outward normal n), facing out of it; empty when a corner lies outside an edge (not convex).
std::vector<Plane> convex_edges(const std::vector<glm::dvec3>& corners, const glm::dvec3& n,
                                double tol) {
    std::vector<Plane> edges;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3& a = corners[i];
        const glm::dvec3 out = glm::normalize(glm::cross(corners[(i + 1) % corners.size()] - a, n));
        edges.push_back({out, glm::dot(out, a)});
    }
    for (const Plane& e : edges) {
        for (const glm::dvec3& c : corners) {
            if (e.signed_distance(c) > tol) return {};
        }
    }
    return edges;
}

std::vector<ConvexPieces::WallPolygon> polygons_of_walls(const Stone& stone,
                                                         const std::vector<std::uint32_t>& walls,
                                                         double tol) {
    std::vector<ConvexPieces::WallPolygon> polygons;
    for (std::uint32_t f : walls) {
        const glm::dvec3& n = stone.facets[f].plane.n;
        std::vector<glm::dvec3> loop;
        for (std::uint32_t v : stone.facets[f].loop) loop.push_back(stone.vertices[v]);
        std::vector<Plane> edges = convex_edges(loop, n, tol);
        if (!edges.empty()) {
            polygons.push_back({f, std::move(edges)});
            continue;
        }
        for (const MeshTriangle& t : stone.triangles) {
            if (t.facet != f) continue;
            const std::vector<glm::dvec3> corners = {stone.vertices[t.v[0]], stone.vertices[t.v[1]],
                                                     stone.vertices[t.v[2]]};
            polygons.push_back({f, convex_edges(corners, n, tol)});
        }
    }
    return polygons;
}

// The planes a split may cut along: the stone's mirrors (its symmetry's reflections, and the
// coordinate planes through its centre, which a design's mirrors usually are) and its reflex
// facets' planes. Duplicates are dropped.
std::vector<Plane> candidate_cuts(const Stone& stone, const std::vector<std::uint32_t>& walls,
                                  double tol) {
    std::vector<Plane> candidates;
    auto add = [&](const Plane& p) {
        for (const Plane& c : candidates) {
            const bool same = std::abs(c.d - p.d) <= tol && glm::length(c.n - p.n) < 1e-9;
            const bool opposite = std::abs(c.d + p.d) <= tol && glm::length(c.n + p.n) < 1e-9;
            if (same || opposite) return;
        }
        candidates.push_back(p);
    };
    for (const glm::dmat3& m : stone.symmetry) {
        // A reflection is I - 2 n nᵀ: (I - m) / 2 = n nᵀ, whose largest column is along n.
        if (glm::determinant(m) > 0.0) continue;
        const glm::dmat3 nn = 0.5 * (glm::dmat3(1.0) - m);
        if (std::abs(nn[0][0] + nn[1][1] + nn[2][2] - 1.0) > 1e-9) continue;  // not a mirror
        glm::dvec3 n = nn[0];
        for (int i = 1; i < 3; ++i) {
            if (glm::length(nn[i]) > glm::length(n)) n = nn[i];
        }
        add(Plane{glm::normalize(n), 0.0});
    }
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        add(Plane{n, 0.0});
    }
    for (std::uint32_t f : walls) {
        // A stone with more pocket walls than this needs more pieces than a split may have;
        // the cap bounds the search (candidates to the power of the cuts) on such a stone.
        if (candidates.size() >= kMaxCandidates) break;
        add(stone.facets[f].plane);
    }
    return candidates;
}

}  // namespace

std::optional<ConvexPieces> ConvexPieces::split(const Stone& stone) {
    if (stone.convex || stone.facets.empty()) return std::nullopt;
    // Corners within a millionth of the stone's size count as on a plane, as
    // stone_from_triangles judges convexity (kPlanarRelative).
    const double tol = 1e-6 * bounding_radius(stone.vertices);
    std::vector<std::uint32_t> walls = walls_of_pockets(stone, tol);
    const Splitter splitter(stone, candidate_cuts(stone, walls, tol), tol);
    auto partition = splitter.best({}, kMaxPieces);
    if (!partition || partition->pieces.size() < 2) return std::nullopt;
    ConvexPieces pieces;
    pieces.nodes_ = std::move(partition->nodes);
    pieces.pieces_ = std::move(partition->pieces);
    pieces.wall_polygons_ = polygons_of_walls(stone, walls, tol);
    pieces.pocket_walls_ = std::move(walls);
    return pieces;
}

int ConvexPieces::locate(const glm::dvec3& p, const glm::dvec3& d, double on_cut) const {
    if (nodes_.empty()) return 0;
    int child = 0;
    while (child >= 0) {
        const Node& node = nodes_[static_cast<std::size_t>(child)];
        const double s = node.cut.signed_distance(p);
        const bool below = s < -on_cut || (s <= on_cut && glm::dot(node.cut.n, d) <= 0.0);
        child = below ? node.below : node.above;
    }
    return -1 - child;
}

}  // namespace gem
