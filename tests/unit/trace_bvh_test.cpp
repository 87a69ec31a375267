// The BVH's nearest hit against a brute-force loop over every triangle, with a different
// ray/triangle method (Möller & Trumbore, "Fast, minimum storage ray-triangle intersection",
// J. Graphics Tools 2(1), 1997) so that the two share no code.

#include <gtest/gtest.h>

#include <limits>

#include "trace/intersector.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

bool moller_trumbore(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                     const glm::dvec3& b, const glm::dvec3& c, double& t) {
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, q) / det;
    return true;
}

struct BruteHit {
    double t = std::numeric_limits<double>::infinity();
    std::uint32_t facet = kNoFacet;
};

// Nearest hit with t > 0 on a triangle whose facet faces the ray (side −1) or not (+1).
BruteHit brute_force(const Stone& s, const glm::dvec3& o, const glm::dvec3& d, double side,
                     std::uint32_t skip) {
    BruteHit best;
    for (const MeshTriangle& tri : s.triangles) {
        if (tri.facet == skip) continue;
        if (glm::dot(s.facets[tri.facet].plane.n, d) * side <= 0.0) continue;
        double t = 0.0;
        if (moller_trumbore(o, d, s.vertices[tri.v[0]], s.vertices[tri.v[1]], s.vertices[tri.v[2]],
                            t) &&
            t > 0.0 && t < best.t) {
            best = {t, tri.facet};
        }
    }
    return best;
}

TEST(TraceBvh, NearestHitMatchesBruteForce) {
    // 40 tips: 80 top and 80 bottom fan triangles and 160 side triangles.
    const Stone stone = test::star_prism_stone(40, 3.0, 2.2, 1.0);
    ASSERT_EQ(stone.triangles.size(), 320u);
    const auto bvh = make_bvh_intersector(stone);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> box(-3.0, 3.0);
    int entries = 0, exits = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::dvec3 target{box(rng), box(rng) / 2.0, box(rng)};
        const glm::dvec3 d = test::random_unit(rng);
        const glm::dvec3 o = target - 8.0 * d;
        const BruteHit expected = brute_force(stone, o, d, -1.0, kNoFacet);
        SurfaceHit hit;
        const bool found = bvh->next_entry(o, d, kNoFacet, hit);
        ASSERT_EQ(found, expected.facet != kNoFacet) << i;
        if (!found) continue;
        ++entries;
        ASSERT_NEAR(hit.t, expected.t, 1e-9) << i;
        ASSERT_EQ(hit.facet, expected.facet) << i;

        // From the entry point into the solid: the nearest leaving facet.
        glm::dvec3 in = test::random_unit(rng);
        const glm::dvec3& n = stone.facets[hit.facet].plane.n;
        if (glm::dot(in, n) > 0.0) in = -in;
        const BruteHit leave = brute_force(stone, hit.point, in, 1.0, hit.facet);
        SurfaceHit exit;
        ASSERT_TRUE(bvh->next_exit(hit.point, in, hit.facet, exit)) << i;
        ASSERT_NE(leave.facet, kNoFacet) << i;
        ++exits;
        ASSERT_NEAR(exit.t, leave.t, 1e-9) << i;
        ASSERT_EQ(exit.facet, leave.facet) << i;
    }
    // The targets fill the bounding box, most of which is inside the star.
    EXPECT_GT(entries, 30000);
    EXPECT_EQ(exits, entries);
}

}  // namespace
}  // namespace gem
