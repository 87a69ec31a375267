// A non-convex stone's convex pieces (trace/convex_pieces.hpp) against its triangles: the
// pieces fill exactly the solid (points tested by counting triangle crossings, which shares no
// code with the split), and the pieces' intersector finds every exit and entry the triangle
// BVH finds, on the rays the exit searches are tested on (trace_exit_rays.hpp's kinds: pixel
// rays followed inside, rays aimed at corners and edges, rays starting on them) plus the rays
// that leave the stone and may come back through its cleft.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "optics/fresnel.hpp"
#include "picture/camera.hpp"
#include "trace/convex_pieces.hpp"
#include "trace/intersector.hpp"
#include "trace/ray_triangle.hpp"
#include "trace_cut_stones.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

// Inside by the parity of triangle crossings along a random direction (the watertight test,
// trace/ray_triangle.hpp: a ray through an edge is counted once).
bool inside_by_parity(const Stone& s, const glm::dvec3& p, std::mt19937_64& rng) {
    const ShearedRay ray(p, test::random_unit(rng));
    int crossings = 0;
    for (const MeshTriangle& tri : s.triangles) {
        double t = 0.0;
        crossings += intersect_watertight(ray, s.vertices[tri.v[0]], s.vertices[tri.v[1]],
                                          s.vertices[tri.v[2]], t) &&
                     t > 0.0;
    }
    return crossings % 2 == 1;
}

// How many pieces hold p, each being the intersection of its planes.
int pieces_holding(const Stone& s, const ConvexPieces& pieces, const glm::dvec3& p) {
    int holding = 0;
    for (const ConvexPieces::Piece& piece : pieces.pieces()) {
        bool in = true;
        for (std::uint32_t f : piece.facets) in = in && s.facets[f].plane.signed_distance(p) < 0.0;
        for (const Plane& c : piece.cuts) in = in && c.signed_distance(p) < 0.0;
        holding += in;
    }
    return holding;
}

void expect_pieces_fill_the_solid(const Stone& s, const ConvexPieces& pieces) {
    std::mt19937_64 rng(11);
    const double r = bounding_radius(s.vertices);
    std::uniform_real_distribution<double> box(-r, r);
    int inside = 0, wrong = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(box(rng), box(rng), box(rng));
        const bool in = inside_by_parity(s, p, rng);
        const int holding = pieces_holding(s, pieces, p);
        inside += in;
        if (holding != (in ? 1 : 0) && ++wrong <= 5) {
            ADD_FAILURE() << s.name << ": (" << p.x << ", " << p.y << ", " << p.z << ") "
                          << (in ? "inside" : "outside") << " the triangles, in " << holding
                          << " pieces";
        }
    }
    EXPECT_EQ(wrong, 0) << s.name;
    EXPECT_GT(inside, 1000) << s.name;
}

struct Tally {
    int exits = 0;
    int entries = 0;
    int reentries = 0;  // entries found: rays that come back through a cleft
    int disagreements = 0;
};

// Two hits agree on t, and on the facet unless the point lies on both (an edge or a corner).
bool same_hit(const Stone& s, const SurfaceHit& a, const SurfaceHit& b, double tol) {
    if (std::abs(a.t - b.t) > tol) return false;
    if (a.facet == b.facet) return true;
    return std::abs(s.facets[a.facet].plane.signed_distance(b.point)) <= tol &&
           std::abs(s.facets[b.facet].plane.signed_distance(a.point)) <= tol;
}

class Checker {
  public:
    explicit Checker(const Stone& s, const ConvexPieces& pieces)
        : s_(s),
          triangles_(make_bvh_intersector(s)),
          pieces_(make_pieces_intersector(s, pieces)),
          walls_(pieces.pocket_walls()),
          tol_(1e-9 * bounding_radius(s.vertices)) {}

    void exit(const glm::dvec3& o, const glm::dvec3& d, std::uint32_t from) {
        SurfaceHit expected, got;
        const bool found = triangles_->next_exit(o, d, from, expected);
        const bool by_pieces = pieces_->next_exit(o, d, from, got);
        ++tally.exits;
        report(found, by_pieces, expected, got, "exit", o, d, from);
    }

    void entry(const glm::dvec3& o, const glm::dvec3& d, std::uint32_t from) {
        SurfaceHit expected, got;
        const bool found = triangles_->next_entry(o, d, from, expected);
        // Only a pocket's wall sends a ray back in (the shader skips the search otherwise).
        const bool wall = std::find(walls_.begin(), walls_.end(), from) != walls_.end();
        if (found && from != kNoFacet && !wall && ++tally.disagreements <= 5) {
            ADD_FAILURE() << s_.name << ": a ray leaving through facet " << from
                          << ", not a pocket's wall, came back in through " << expected.facet;
        }
        const bool by_pieces = pieces_->next_entry(o, d, from, got);
        ++tally.entries;
        tally.reentries += found;
        report(found, by_pieces, expected, got, "entry", o, d, from);
    }

    const Intersector& triangles() const { return *triangles_; }
    Tally tally;

  private:
    void report(bool found, bool by_pieces, const SurfaceHit& expected, const SurfaceHit& got,
                const char* what, const glm::dvec3& o, const glm::dvec3& d, std::uint32_t from) {
        if (found == by_pieces && (!found || same_hit(s_, expected, got, tol_))) return;
        if (++tally.disagreements > 5) return;
        ADD_FAILURE() << s_.name << " " << what << " from facet " << from << " at (" << o.x << ", "
                      << o.y << ", " << o.z << ") along (" << d.x << ", " << d.y << ", " << d.z
                      << "): triangles " << (found ? "facet " : "none ") << expected.facet << " t "
                      << expected.t << ", pieces " << (by_pieces ? "facet " : "none ") << got.facet
                      << " t " << got.t;
    }

    const Stone& s_;
    std::unique_ptr<Intersector> triangles_;
    std::unique_ptr<Intersector> pieces_;
    std::vector<std::uint32_t> walls_;
    double tol_;
};

// A point inside the solid: the mean of the corners nudged toward a corner, kept when the
// triangles say it is inside.
glm::dvec3 inside_point(const Stone& s, std::mt19937_64& rng) {
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : s.vertices) centre += v;
    centre /= static_cast<double>(s.vertices.size());
    std::uniform_int_distribution<std::size_t> pick(0, s.vertices.size() - 1);
    std::uniform_real_distribution<double> share(0.0, 0.95);
    for (;;) {
        const glm::dvec3 p = centre + share(rng) * (s.vertices[pick(rng)] - centre);
        if (inside_by_parity(s, p, rng)) return p;
    }
}

// The edges where the surface folds inward (a facet across the edge has a corner outside the
// other's plane) and the corners on them. A ray through such an edge grazes the surface there:
// whether it leaves or goes on inside, neither is wrong (the rays that do so have no area), and
// the triangles and the planes may choose differently. The exactly aimed rays skip them.
struct ReflexEdges {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    std::set<std::uint32_t> corners;

    explicit ReflexEdges(const Stone& s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> facets_of;
        for (std::uint32_t f = 0; f < s.facets.size(); ++f) {
            const auto& loop = s.facets[f].loop;
            for (std::size_t i = 0; i < loop.size(); ++i) {
                facets_of[key(loop[i], loop[(i + 1) % loop.size()])].push_back(f);
            }
        }
        const double tol = 1e-9 * bounding_radius(s.vertices);
        for (const auto& [edge, facets] : facets_of) {
            bool folds = false;
            for (std::uint32_t f : facets) {
                for (std::uint32_t g : facets) {
                    for (std::uint32_t v : s.facets[g].loop) {
                        folds = folds || s.facets[f].plane.signed_distance(s.vertices[v]) > tol;
                    }
                }
            }
            if (!folds) continue;
            edges.insert(edge);
            corners.insert(edge.first);
            corners.insert(edge.second);
        }
    }
    static std::pair<std::uint32_t, std::uint32_t> key(std::uint32_t a, std::uint32_t b) {
        return {std::min(a, b), std::max(a, b)};
    }
    bool on_edge(std::uint32_t a, std::uint32_t b) const { return edges.count(key(a, b)) > 0; }
    bool on_corner(std::uint32_t a) const { return corners.count(a) > 0; }
};

// trace_exit_rays.hpp's kinds of ray, followed by the triangles: pixel rays refracted in and
// reflected `depth` times (each exit point's refracted ray out also checked for an entry back),
// rays from inside at corners and edges, and rays from corners and edges inward.
Tally check_every_kind_of_ray(const Stone& s, const ConvexPieces& pieces, int pixel_rays,
                              int depth) {
    Checker check(s, pieces);
    std::mt19937_64 rng(7);
    const double radius = bounding_radius(s.vertices);
    for (int i = 0; i < pixel_rays; ++i) {
        const glm::dvec3 d = test::random_unit(rng);
        const glm::dvec3 side = glm::normalize(glm::cross(d, test::random_unit(rng)));
        std::uniform_real_distribution<double> offset(-radius, radius);
        const glm::dvec3 o = -2.0 * radius * d + offset(rng) * side;
        check.entry(o, d, kNoFacet);
        SurfaceHit hit;
        if (!check.triangles().next_entry(o, d, kNoFacet, hit)) continue;
        auto in = refract(d, s.facets[hit.facet].plane.n, 1.0, test::kDiamondIndex);
        if (!in) continue;
        glm::dvec3 p = hit.point;
        glm::dvec3 dir = *in;
        std::uint32_t from = hit.facet;
        for (int k = 0; k < depth; ++k) {
            check.exit(p, dir, from);
            SurfaceHit out;
            if (!check.triangles().next_exit(p, dir, from, out)) break;
            const glm::dvec3& n = s.facets[out.facet].plane.n;
            if (auto leaving = refract(dir, -n, test::kDiamondIndex, 1.0)) {
                check.entry(out.point, *leaving, out.facet);
            }
            p = out.point;
            dir = reflect(dir, n);
            from = out.facet;
        }
    }
    const ReflexEdges reflex(s);
    for (const Facet& f : s.facets) {
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            const std::uint32_t ia = f.loop[i];
            const std::uint32_t ib = f.loop[(i + 1) % f.loop.size()];
            const glm::dvec3 a = s.vertices[ia];
            const glm::dvec3 b = s.vertices[ib];
            for (double share : {0.0, 0.5, 1.0 / 3.0}) {
                if (share == 0.0 ? reflex.on_corner(ia) : reflex.on_edge(ia, ib)) continue;
                const glm::dvec3 o = inside_point(s, rng);
                check.exit(o, glm::normalize(a + share * (b - a) - o), kNoFacet);
            }
        }
    }
    for (std::uint32_t f = 0; f < s.facets.size(); ++f) {
        const auto& loop = s.facets[f].loop;
        const glm::dvec3 a = s.vertices[loop[0]];
        const glm::dvec3 b = s.vertices[loop[1]];
        for (const glm::dvec3& start : {a, 0.5 * (a + b)}) {
            const bool corner = start == a;
            if (corner ? reflex.on_corner(loop[0]) : reflex.on_edge(loop[0], loop[1])) continue;
            for (int k = 0; k < 8; ++k) {
                // Inward, as the tracer's rays are: from a reflex edge (the cleft's) the way
                // to a point inside may leave the solid at once, and has no exit to find.
                const glm::dvec3 d = glm::normalize(inside_point(s, rng) - start);
                if (inside_by_parity(s, start + 1e-6 * radius * d, rng)) check.exit(start, d, f);
            }
        }
    }
    return check.tally;
}

Stone heart() {
    return make_cut(default_cut_params(CutShape::heart),
                    test::constant_index_material(test::kDiamondIndex))
        .value();
}

TEST(ConvexPieces, TheHeartSplitsInTwoAlongItsMirror) {
    const Stone s = heart();
    ASSERT_FALSE(s.convex);
    const auto pieces = ConvexPieces::split(s);
    ASSERT_TRUE(pieces.has_value());
    ASSERT_EQ(pieces->pieces().size(), 2u);
    ASSERT_EQ(pieces->nodes().size(), 1u);
    // x = 0 (either way round): the heart is built as two mirrored convex halves.
    EXPECT_NEAR(std::abs(pieces->nodes()[0].cut.n.x), 1.0, 1e-12);
    EXPECT_NEAR(pieces->nodes()[0].cut.d, 0.0, 1e-12);
    // The cleft's walls: its girdle, bezel and main facets, either side.
    EXPECT_EQ(pieces->pocket_walls().size(), 6u);
    for (const ConvexPieces::Piece& piece : pieces->pieces()) {
        EXPECT_EQ(piece.cuts.size(), 1u);
        EXPECT_LT(piece.facets.size(), s.facets.size());
    }
    expect_pieces_fill_the_solid(s, *pieces);
}

TEST(ConvexPieces, TheHeartsPiecesFindWhatItsTrianglesFind) {
    const Stone s = heart();
    const auto pieces = ConvexPieces::split(s);
    ASSERT_TRUE(pieces.has_value());
    const Tally t = check_every_kind_of_ray(s, *pieces, 4000, 12);
    EXPECT_EQ(t.disagreements, 0) << "over " << t.exits << " exits and " << t.entries << " entries";
    EXPECT_GT(t.exits, 20000);
    EXPECT_GT(t.reentries, 100);  // rays that come back through the cleft were among them
    std::printf("heart: %d exits, %d entries (%d back in through the cleft)\n", t.exits, t.entries,
                t.reentries);
}

TEST(ConvexPieces, AFourPointedStarSplitsAlongItsDiagonalMirrors) {
    // Tips on the axes, notches on the diagonals: the mirrors through the notches cut it into
    // four kites, each a tip with the centre. The mirrors through the tips leave a notch in
    // every quarter, so two cuts are not enough along them.
    Stone star = test::star_prism_stone(4, 3.0, 1.0, 1.0);
    for (const glm::dvec3& n : {glm::dvec3(1.0, 0.0, 1.0), glm::dvec3(1.0, 0.0, -1.0)}) {
        const glm::dvec3 u = glm::normalize(n);
        star.symmetry.push_back(glm::dmat3(1.0) - 2.0 * glm::outerProduct(u, u));
    }
    const auto four = ConvexPieces::split(star);
    ASSERT_TRUE(four.has_value());
    EXPECT_EQ(four->pieces().size(), 4u);
    EXPECT_EQ(four->nodes().size(), 3u);
    expect_pieces_fill_the_solid(star, *four);
    const Tally t = check_every_kind_of_ray(star, *four, 2000, 12);
    EXPECT_EQ(t.disagreements, 0) << "over " << t.exits << " exits and " << t.entries;
    EXPECT_GT(t.reentries, 50);

    // Without the diagonal mirrors no split of four pieces is convex; nor with forty tips.
    EXPECT_FALSE(ConvexPieces::split(test::star_prism_stone(4, 3.0, 1.0, 1.0)).has_value());
    EXPECT_FALSE(ConvexPieces::split(test::star_prism_stone(40, 3.0, 2.2, 1.0)).has_value());
    // A convex stone is not split.
    EXPECT_FALSE(ConvexPieces::split(test::round_diamond(6.5)).has_value());
}

TEST(ConvexPieces, LocatingAPointOnACutFollowsTheDirection) {
    const auto pieces = ConvexPieces::split(heart());
    ASSERT_TRUE(pieces.has_value());
    const glm::dvec3 on_cut(0.0, 0.1, 0.0);
    const int right = pieces->locate(on_cut, {1.0, 0.0, 0.0}, 1e-9);
    const int left = pieces->locate(on_cut, {-1.0, 0.0, 0.0}, 1e-9);
    EXPECT_NE(right, left);
    EXPECT_EQ(pieces->locate({0.5, 0.1, 0.0}, {-1.0, 0.0, 0.0}, 1e-9), right);
    EXPECT_EQ(pieces->locate({-0.5, 0.1, 0.0}, {1.0, 0.0, 0.0}, 1e-9), left);
}

}  // namespace
}  // namespace gem
