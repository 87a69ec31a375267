// The facet walk (trace/facet_walk.hpp) against the full search over every facet
// (convex_intersector.cpp), which it must agree with exactly: the same exit facet and the same
// t on every ray, never an endless walk. Rays: internal paths of pixel rays (entry refraction,
// then reflections, as the tracer follows them), rays from inside aimed exactly at corners and
// at points on edges, and rays that start on a corner or an edge.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "import/load_model.hpp"
#include "optics/fresnel.hpp"
#include "trace/facet_walk.hpp"
#include "trace/intersector.hpp"
#include "trace_cut_stones.hpp"
#include "util/cube_faces.hpp"

namespace gem {
namespace {

struct Tally {
    int rays = 0;
    int disagreements = 0;
    WalkCost cost;
};

// One exit found both ways.
void check(const FacetWalk& walk, const Intersector& full, const glm::dvec3& o, const glm::dvec3& d,
           std::uint32_t from, Tally& tally, const std::string& stone) {
    SurfaceHit expected;
    SurfaceHit got;
    const bool found = full.next_exit(o, d, from, expected);
    const bool walked = walk.next_exit(o, d, from, got, &tally.cost);
    ++tally.rays;
    if (found != walked || (found && (expected.facet != got.facet || expected.t != got.t))) {
        if (++tally.disagreements <= 5) {
            ADD_FAILURE() << stone << ": from facet " << from << " at (" << o.x << ", " << o.y
                          << ", " << o.z << ") along (" << d.x << ", " << d.y << ", " << d.z
                          << "): full search facet " << expected.facet << " t " << expected.t
                          << ", walk facet " << got.facet << " t " << got.t;
        }
    }
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
}

// A point strictly inside: the mean of the corners, nudged toward a random vertex.
glm::dvec3 inside_point(const Stone& s, std::mt19937_64& rng) {
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : s.vertices) centre += v;
    centre /= static_cast<double>(s.vertices.size());
    std::uniform_int_distribution<std::size_t> pick(0, s.vertices.size() - 1);
    std::uniform_real_distribution<double> share(0.0, 0.95);
    return centre + share(rng) * (s.vertices[pick(rng)] - centre);
}

Tally walk_every_kind_of_ray(const Stone& s, int pixel_rays, int depth) {
    const FacetWalk walk(s);
    const auto full = make_convex_intersector(s);
    std::mt19937_64 rng(7);
    Tally tally;
    const double radius = [&] {
        double r = 0.0;
        for (const glm::dvec3& v : s.vertices) r = std::max(r, glm::length(v));
        return r;
    }();
    // Internal paths of rays from outside, reflected inside as the tracer does.
    for (int i = 0; i < pixel_rays; ++i) {
        const glm::dvec3 d = random_unit(rng);
        glm::dvec3 side = glm::normalize(glm::cross(d, random_unit(rng)));
        std::uniform_real_distribution<double> offset(-radius, radius);
        const glm::dvec3 o = -2.0 * radius * d + offset(rng) * side;
        SurfaceHit hit;
        if (!full->next_entry(o, d, kNoFacet, hit)) continue;
        auto in = refract(d, s.facets[hit.facet].plane.n, 1.0, test::kDiamondIndex);
        if (!in) continue;
        glm::dvec3 p = hit.point;
        glm::dvec3 dir = *in;
        std::uint32_t from = hit.facet;
        for (int k = 0; k < depth; ++k) {
            check(walk, *full, p, dir, from, tally, s.name);
            SurfaceHit out;
            if (!full->next_exit(p, dir, from, out)) break;
            p = out.point;
            dir = reflect(dir, s.facets[out.facet].plane.n);
            from = out.facet;
        }
    }
    // Aimed exactly at every corner and at points along every edge, from inside.
    for (const Facet& f : s.facets) {
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            const glm::dvec3 a = s.vertices[f.loop[i]];
            const glm::dvec3 b = s.vertices[f.loop[(i + 1) % f.loop.size()]];
            for (double share : {0.0, 0.5, 1.0 / 3.0}) {
                const glm::dvec3 target = a + share * (b - a);
                const glm::dvec3 o = inside_point(s, rng);
                check(walk, *full, o, glm::normalize(target - o), kNoFacet, tally, s.name);
            }
        }
    }
    // Starting on a corner or an edge of facet f, into the stone.
    for (std::uint32_t f = 0; f < s.facets.size(); ++f) {
        const auto& loop = s.facets[f].loop;
        const glm::dvec3 a = s.vertices[loop[0]];
        const glm::dvec3 b = s.vertices[loop[1]];
        for (const glm::dvec3& start : {a, 0.5 * (a + b)}) {
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 d = glm::normalize(inside_point(s, rng) - start);
                check(walk, *full, start, d, f, tally, s.name);
            }
        }
    }
    return tally;
}

TEST(FacetWalk, AgreesWithTheFullSearchOnEveryConvexCut) {
    for (const Stone& s : test::all_cuts()) {
        if (!s.convex) continue;  // the heart: traced through its triangles
        const Tally t = walk_every_kind_of_ray(s, 4000, 12);
        EXPECT_EQ(t.disagreements, 0) << s.name << " over " << t.rays << " rays";
        EXPECT_GT(t.rays, 20000) << s.name;
        EXPECT_EQ(t.cost.fell_back, 0u) << s.name;
        EXPECT_LT(t.cost.longest, FacetWalk::kMaxSteps) << s.name;
        // The point of the walk: a handful of planes per exit, not all of them.
        const double planes = static_cast<double>(t.cost.planes) / t.cost.walks;
        EXPECT_LT(planes, 0.5 * s.facets.size()) << s.name;
        std::printf(
            "%-16s %3zu facets: %d rays, %.1f planes and %.2f steps per exit, longest "
            "walk %d steps\n",
            s.name.c_str(), s.facets.size(), t.rays, planes,
            static_cast<double>(t.cost.steps) / t.cost.walks, t.cost.longest);
    }
}

TEST(FacetWalk, AgreesWithTheFullSearchOnAGemCadDesign) {
    auto stone = load_model(std::filesystem::path(GEM_SHARED_DATA_DIR) / "gemcad" / "SRB.asc");
    ASSERT_TRUE(stone.ok()) << stone.error();
    ASSERT_TRUE(stone.value().convex);
    const Tally t = walk_every_kind_of_ray(stone.value(), 4000, 12);
    EXPECT_EQ(t.disagreements, 0) << "over " << t.rays << " rays";
    EXPECT_EQ(t.cost.fell_back, 0u);
}

TEST(FacetWalk, AnyStartingFacetEndsOnTheExit) {
    // The guess only saves time: from every facet that faces forward the walk still ends on
    // the full search's exit (one that does not face forward is a full search).
    const Stone s = test::all_cuts().front();  // the round brilliant
    const FacetWalk walk(s);
    const auto full = make_convex_intersector(s);
    std::mt19937_64 rng(11);
    int walks = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 o = inside_point(s, rng);
        const glm::dvec3 d = random_unit(rng);
        SurfaceHit expected;
        ASSERT_TRUE(full->next_exit(o, d, kNoFacet, expected));
        for (std::uint32_t start = 0; start < s.facets.size(); ++start) {
            if (glm::dot(s.facets[start].plane.n, d) <= 0.0) continue;
            WalkCost cost;
            SurfaceHit got;
            ASSERT_TRUE(walk.next_exit_from(o, d, kNoFacet, start, got, &cost));
            ASSERT_EQ(got.facet, expected.facet) << "from facet " << start;
            ASSERT_EQ(cost.fell_back, 0u);
            ++walks;
        }
    }
    EXPECT_GT(walks, 5000);
}

TEST(FacetWalk, EdgeNeighboursCloseEveryFacet) {
    // Every edge of every facet's loop has a facet on its other side among the edge
    // neighbours, and neighbourhood is mutual.
    for (const Stone& s : test::all_cuts()) {
        const FacetAdjacency adj = facet_adjacency(s);
        ASSERT_EQ(adj.facets(), s.facets.size());
        for (std::uint32_t f = 0; f < s.facets.size(); ++f) {
            EXPECT_GE(adj.edge_count[f], 3u) << s.name << " facet " << f;
            EXPECT_LE(adj.edge_count[f], s.facets[f].loop.size()) << s.name << " facet " << f;
            for (std::uint32_t i = 0; i < adj.edge_count[f]; ++i) {
                const std::uint32_t g = adj.edges_of(f)[i];
                const std::uint32_t* back = adj.edges_of(g);
                EXPECT_NE(std::find(back, back + adj.edge_count[g], f), back + adj.edge_count[g])
                    << s.name << ": " << f << " lists " << g << " but not the other way";
            }
        }
    }
}

TEST(FacetWalk, CubeTexelsRoundTrip) {
    // The guess map's addressing is GL's (the GPU reads the same map as a cube texture).
    for (int face = 0; face < 6; ++face) {
        for (int t = 0; t < 8; ++t) {
            for (int s = 0; s < 8; ++s) {
                const CubeTexel c =
                    cube_face_texel(cube_face_direction(face, (s + 0.5) / 8, (t + 0.5) / 8), 8);
                EXPECT_EQ(c.face, face);
                EXPECT_EQ(c.s, s);
                EXPECT_EQ(c.t, t);
            }
        }
    }
    // Fixed points of the GL rule: +x's centre is (1, 0, 0); its texel s = 0, t = 0 looks
    // toward +z and +y (sc = −rz, tc = −ry).
    const glm::dvec3 corner = cube_face_direction(0, 0.25, 0.25);
    EXPECT_GT(corner.x, 0.0);
    EXPECT_GT(corner.y, 0.0);
    EXPECT_GT(corner.z, 0.0);
}

}  // namespace
}  // namespace gem
