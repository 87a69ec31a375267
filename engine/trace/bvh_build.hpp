#pragma once
// A bounding volume hierarchy over triangles, built once: median split on the longest axis of
// the triangles' centroids, nodes in one flat array where an inner node's left child follows
// it. The CPU's intersector of non-convex solids (bvh_intersector.cpp) and the GPU's metal,
// which traces what it reflects of its piece (gpu/piece_sight.hpp), both walk it.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

struct BvhNode {
    glm::dvec3 lo{0.0}, hi{0.0};
    std::uint32_t first = 0;  // inner: index of the right child (left is next); leaf: triangle
    std::uint32_t count = 0;  // triangles in a leaf (in `order`, from `first`), 0 inner
};

struct Bvh {
    std::vector<BvhNode> nodes;        // the root first; empty for no triangles
    std::vector<std::uint32_t> order;  // the triangles as the leaves hold them
};

using TriangleCorners = std::array<glm::dvec3, 3>;

// Leaves of at most `leaf_size` triangles, unless `max_depth` stops the split first (a walk's
// fixed stack must hold two nodes a level); every box is grown by `pad` on each side, so a
// slab test stays conservative for rays grazing a face.
Bvh build_bvh(const std::vector<TriangleCorners>& triangles, std::uint32_t leaf_size, int max_depth,
              double pad);

}  // namespace gem
