// The facet walk (trace/facet_walk.hpp) against the full search over every facet
// (convex_intersector.cpp), which it must agree with exactly: the same exit facet and the same
// t on every ray (trace_exit_rays.hpp), never an endless walk.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "import/load_model.hpp"
#include "trace/facet_walk.hpp"
#include "trace/intersector.hpp"
#include "trace_cut_stones.hpp"
#include "trace_exit_rays.hpp"
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

Tally walk_every_kind_of_ray(const Stone& s, int pixel_rays, int depth) {
    const FacetWalk walk(s);
    const auto full = make_convex_intersector(s);
    Tally tally;
    test::for_every_kind_of_exit_ray(
        s, pixel_rays, depth, [&](const glm::dvec3& o, const glm::dvec3& d, std::uint32_t from) {
            check(walk, *full, o, d, from, tally, s.name);
        });
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
    auto stone = load_model(std::filesystem::path(GEM_TEST_DATA_DIR) / "gemcad" / "SRB.asc");
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
        const glm::dvec3 o = test::inside_point(s, rng);
        const glm::dvec3 d = test::random_unit(rng);
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
