// The hierarchy's shape, checked against its definition (bvh_build.hpp) rather than by walking
// it: every triangle held by exactly one leaf, every box holding what lies under it, children
// where the flat layout puts them, and leaves no larger than asked unless the depth ran out.
// (Walks of it are held to brute force in trace_bvh_test.cpp and, on the GPU, by the metal
// seeing its piece in gpu_piece_test.cpp.)

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "trace/bvh_build.hpp"

namespace gem {
namespace {

std::vector<TriangleCorners> scattered(int count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> place(-10.0, 10.0), size(-0.5, 0.5);
    std::vector<TriangleCorners> triangles;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c(place(random), place(random), place(random));
        triangles.push_back({c + glm::dvec3(size(random), size(random), size(random)),
                             c + glm::dvec3(size(random), size(random), size(random)),
                             c + glm::dvec3(size(random), size(random), size(random))});
    }
    return triangles;
}

bool holds(const BvhNode& box, const glm::dvec3& p) {
    return glm::all(glm::lessThanEqual(box.lo, p)) && glm::all(glm::lessThanEqual(p, box.hi));
}

// Checks the subtree at `index` (depth `depth`) and counts its leaves' triangles in `seen`.
void check(const Bvh& bvh, const std::vector<TriangleCorners>& triangles, std::uint32_t index,
           int depth, std::uint32_t leaf_size, int max_depth, std::vector<int>& seen) {
    ASSERT_LT(index, bvh.nodes.size());
    const BvhNode& node = bvh.nodes[index];
    if (node.count > 0) {
        EXPECT_TRUE(node.count <= leaf_size || depth == max_depth)
            << node.count << " triangles in a leaf at depth " << depth;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            ASSERT_LT(i, bvh.order.size());
            ++seen[bvh.order[i]];
            for (const glm::dvec3& corner : triangles[bvh.order[i]]) {
                EXPECT_TRUE(holds(node, corner)) << "a leaf's box misses its triangle";
            }
        }
        return;
    }
    EXPECT_LT(depth, max_depth);
    const std::uint32_t left = index + 1, right = node.first;
    ASSERT_GT(right, left) << "the right child follows the left subtree";
    for (const std::uint32_t child : {left, right}) {
        EXPECT_TRUE(holds(node, bvh.nodes[child].lo) && holds(node, bvh.nodes[child].hi))
            << "a box misses its child's";
        check(bvh, triangles, child, depth + 1, leaf_size, max_depth, seen);
    }
}

TEST(BvhBuild, EveryTriangleIsInOneLeafWhoseBoxesHoldIt) {
    for (const int count : {1, 2, 5, 100, 1000}) {
        const std::vector<TriangleCorners> triangles = scattered(count, 7u + count);
        const Bvh bvh = build_bvh(triangles, 4, 30, 1e-3);
        std::vector<int> seen(triangles.size(), 0);
        check(bvh, triangles, 0, 0, 4, 30, seen);
        for (std::size_t i = 0; i < seen.size(); ++i) {
            EXPECT_EQ(seen[i], 1) << "triangle " << i << " of " << count;
        }
        // A median split leaves at least 2 triangles a leaf (a node of 5 or more splits into
        // halves of 2 or more), so at most ceil(n / 2) leaves and twice that less one nodes.
        EXPECT_LE(bvh.nodes.size(), 2 * ((triangles.size() + 1) / 2) - 1) << count;
    }
}

TEST(BvhBuild, ItsBoxesArePaddedAsAsked) {
    const TriangleCorners one{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 2, 0)};
    const Bvh bvh = build_bvh({one}, 4, 30, 0.25);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].lo, glm::dvec3(-0.25, -0.25, -0.25));
    EXPECT_EQ(bvh.nodes[0].hi, glm::dvec3(1.25, 2.25, 0.25));
    EXPECT_EQ(bvh.nodes[0].count, 1u);
}

TEST(BvhBuild, TheDepthBoundStopsTheSplitWithLargerLeaves) {
    const std::vector<TriangleCorners> triangles = scattered(200, 3u);
    const Bvh bvh = build_bvh(triangles, 1, 3, 0.0);
    std::vector<int> seen(triangles.size(), 0);
    check(bvh, triangles, 0, 0, 1, 3, seen);
    for (const int s : seen) EXPECT_EQ(s, 1);
    // Three levels: eight leaves of 25.
    int leaves = 0;
    for (const BvhNode& node : bvh.nodes) leaves += node.count > 0 ? 1 : 0;
    EXPECT_EQ(leaves, 8);
}

TEST(BvhBuild, NoTrianglesNoTree) {
    const Bvh bvh = build_bvh({}, 4, 30, 0.0);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.order.empty());
}

}  // namespace
}  // namespace gem
