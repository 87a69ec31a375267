#include "trace/bvh_build.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace gem {
namespace {

struct Builder {
    const std::vector<TriangleCorners>& triangles;
    std::uint32_t leaf_size;
    int max_depth;
    double pad;
    Bvh bvh;

    // The subtree over order[begin, end); returns its node's index.
    std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth) {
        const auto index = static_cast<std::uint32_t>(bvh.nodes.size());
        bvh.nodes.emplace_back();
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        glm::dvec3 clo = lo, chi = hi;  // the centroids' bounds
        for (std::uint32_t i = begin; i < end; ++i) {
            const TriangleCorners& t = triangles[bvh.order[i]];
            lo = glm::min(glm::min(lo, t[0]), glm::min(t[1], t[2]));
            hi = glm::max(glm::max(hi, t[0]), glm::max(t[1], t[2]));
            const glm::dvec3 c = (t[0] + t[1] + t[2]) / 3.0;
            clo = glm::min(clo, c);
            chi = glm::max(chi, c);
        }
        bvh.nodes[index].lo = lo - glm::dvec3(pad);
        bvh.nodes[index].hi = hi + glm::dvec3(pad);
        const glm::dvec3 extent = chi - clo;
        if (end - begin <= leaf_size || depth >= max_depth ||
            std::max({extent.x, extent.y, extent.z}) <= 0.0) {
            bvh.nodes[index].first = begin;
            bvh.nodes[index].count = end - begin;
            return index;
        }
        const int axis =
            extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + mid,
                         bvh.order.begin() + end, [&](std::uint32_t a, std::uint32_t b) {
                             const TriangleCorners& ta = triangles[a];
                             const TriangleCorners& tb = triangles[b];
                             return ta[0][axis] + ta[1][axis] + ta[2][axis] <
                                    tb[0][axis] + tb[1][axis] + tb[2][axis];
                         });
        build(begin, mid, depth + 1);
        bvh.nodes[index].first = build(mid, end, depth + 1);
        return index;
    }
};

}  // namespace

Bvh build_bvh(const std::vector<TriangleCorners>& triangles, std::uint32_t leaf_size, int max_depth,
              double pad) {
    Builder b{triangles, std::max(leaf_size, 1u), max_depth, pad, {}};
    if (triangles.empty()) return {};
    b.bvh.order.resize(triangles.size());
    std::iota(b.bvh.order.begin(), b.bvh.order.end(), 0u);
    b.bvh.nodes.reserve(2 * triangles.size() / b.leaf_size + 2);
    b.build(0, static_cast<std::uint32_t>(triangles.size()), 0);
    return std::move(b.bvh);
}

}  // namespace gem
