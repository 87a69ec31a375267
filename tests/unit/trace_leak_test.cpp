// No leaks: a million rays per stone aimed at vertices, edges and facet interiors. Every ray
// that enters must leave through a point on the surface, through both intersectors.

#include <chrono>
#include <cstdio>

#include "trace_cut_stones.hpp"
#include "trace_leak_check.hpp"

namespace gem {
namespace {

constexpr int kRays = 1'000'000;

TEST(TraceLeak, CubeThroughPlanes) {
    const Stone cube = test::box_stone(1.0, 1.0, 1.0);
    test::expect_no_leaks(cube, *make_convex_intersector(cube), kRays, 1.5, 1);
}

TEST(TraceLeak, CubeThroughBvh) {
    const Stone cube = test::box_stone(1.0, 1.0, 1.0);
    test::expect_no_leaks(cube, *make_bvh_intersector(cube), kRays, 1.5, 2);
}

TEST(TraceLeak, NonConvexStarPrismThroughBvh) {
    const Stone star = test::star_prism_stone(5, 3.0, 1.2, 0.8);
    test::expect_no_leaks(star, *make_bvh_intersector(star), kRays, 2.417, 3);
}

// Convex cuts go through the planes, the heart (non-convex) through the BVH; every cut also
// through the BVH, which is what a mesh import of it would use.
TEST(TraceLeak, EveryCut) {
    std::uint64_t seed = 10;
    for (const Stone& cut : test::all_cuts()) {
        const auto start = std::chrono::steady_clock::now();
        test::expect_no_leaks(cut, *make_intersector(cut), kRays, test::kDiamondIndex, ++seed);
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        std::printf("%-16s %zu facets, %zu triangles, %s: %.2f s per million rays\n",
                    cut.name.c_str(), cut.facets.size(), cut.triangles.size(),
                    cut.convex ? "planes" : "bvh", took.count());
        if (cut.convex) {
            test::expect_no_leaks(cut, *make_bvh_intersector(cut), kRays / 10, test::kDiamondIndex,
                                  ++seed);
        }
    }
}

}  // namespace
}  // namespace gem
