// Non-convex stones: the facet triangles in a bounding volume hierarchy (bvh_build.hpp),
// traversed with a fixed-size stack so a query allocates nothing. Triangles are tested with the
// watertight test (ray_triangle.hpp).
//
// Self-intersection: a ray that leaves a facet is never tested against that facet again. A
// straight line crosses a plane at most once, so this is exact for planar facets and needs no
// offset of the origin. What remains is a start point on an edge, where the neighbouring
// facet's plane passes through the origin: hits down to t = -epsilon (1e-9 of the stone's
// diagonal, far above double rounding of millimetre coordinates and far below any facet size)
// are accepted, so a ray that leaves the edge straight through the neighbour is caught there
// instead of being lost outside the solid.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

#include "trace/bvh_build.hpp"
#include "trace/intersector.hpp"
#include "trace/ray_triangle.hpp"

namespace gem {
namespace {

struct TriangleRecord {
    glm::dvec3 v0, v1, v2;
    glm::dvec3 normal;  // the facet's outward normal, for entering / leaving
    std::uint32_t facet;
};

constexpr std::uint32_t kLeafSize = 4;
constexpr int kStackSize = 64;  // depth of a median-split tree is about log2(triangles / 4)

class BvhIntersector final : public Intersector {
  public:
    explicit BvhIntersector(const Stone& stone) {
        assert(!stone.triangles.empty());
        glm::dvec3 lo(std::numeric_limits<double>::infinity());
        glm::dvec3 hi(-std::numeric_limits<double>::infinity());
        std::vector<TriangleRecord> records;
        records.reserve(stone.triangles.size());
        for (const MeshTriangle& tri : stone.triangles) {
            assert(tri.facet < stone.facets.size());
            const TriangleRecord r{stone.vertices[tri.v[0]], stone.vertices[tri.v[1]],
                                   stone.vertices[tri.v[2]], stone.facets[tri.facet].plane.n,
                                   tri.facet};
            for (const glm::dvec3& p : {r.v0, r.v1, r.v2}) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            records.push_back(r);
        }
        epsilon_ = 1e-9 * glm::length(hi - lo);
        std::vector<TriangleCorners> corners;
        corners.reserve(records.size());
        for (const TriangleRecord& r : records) corners.push_back({r.v0, r.v1, r.v2});
        Bvh bvh = build_bvh(corners, kLeafSize, kStackSize - 2, epsilon_);
        nodes_ = std::move(bvh.nodes);
        triangles_.reserve(records.size());
        for (std::uint32_t i : bvh.order) triangles_.push_back(records[i]);
    }

    bool next_entry(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                    SurfaceHit& hit) const override {
        return nearest(origin, direction, from_facet, -1.0, hit);
    }

    bool next_exit(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                   SurfaceHit& hit) const override {
        return nearest(origin, direction, from_facet, 1.0, hit) ||
               touching(origin, direction, from_facet, hit);
    }

    bool can_reenter() const override { return true; }

  private:
    // Nearest hit on a triangle whose facet normal n has sign(n·d) == side.
    bool nearest(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                 double side, SurfaceHit& hit) const {
        const ShearedRay sheared(origin, direction);
        glm::dvec3 inv;
        for (int i = 0; i < 3; ++i) {
            // A huge finite value instead of infinity avoids 0 · inf = NaN in the slab test.
            inv[i] = direction[i] != 0.0 ? 1.0 / direction[i] : 1e300;
        }
        const double t_min = -epsilon_;
        double t_best = std::numeric_limits<double>::infinity();
        std::uint32_t best = kNoFacet;
        std::array<std::uint32_t, kStackSize> stack;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const BvhNode& node = nodes_[stack[--top]];
            const glm::dvec3 t0 = (node.lo - origin) * inv;
            const glm::dvec3 t1 = (node.hi - origin) * inv;
            const glm::dvec3 near = glm::min(t0, t1);
            const glm::dvec3 far = glm::max(t0, t1);
            const double enter = std::max({near.x, near.y, near.z, t_min});
            const double leave = std::min({far.x, far.y, far.z, t_best});
            if (enter > leave) continue;
            if (node.count == 0) {
                assert(top + 2 <= kStackSize);
                stack[top++] = node.first;
                stack[top++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
                continue;
            }
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const TriangleRecord& tri = triangles_[i];
                if (tri.facet == from_facet) continue;
                if (glm::dot(tri.normal, direction) * side <= 0.0) continue;
                double t = 0.0;
                if (!intersect_watertight(sheared, tri.v0, tri.v1, tri.v2, t)) continue;
                if (t > t_min && t < t_best) {
                    t_best = t;
                    best = tri.facet;
                }
            }
        }
        if (best == kNoFacet) return false;
        const double t = std::max(t_best, 0.0);
        hit.t = t;
        hit.point = origin + t * direction;
        hit.facet = best;
        return true;
    }

    // A ray that starts exactly on an edge or a vertex and leaves at once through a
    // neighbouring facet has that facet's edge at t = 0, where the sheared edge functions are
    // rounding noise and may reject it. Only then (no exit found at all) the neighbours
    // touching the origin are searched directly, and the ray leaves where it stands through
    // the one it leaves most steeply.
    bool touching(const glm::dvec3& origin, const glm::dvec3& direction, std::uint32_t from_facet,
                  SurfaceHit& hit) const {
        double steepest = 0.0;
        std::uint32_t best = kNoFacet;
        std::array<std::uint32_t, kStackSize> stack;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const BvhNode& node = nodes_[stack[--top]];
            if (glm::any(glm::lessThan(origin, node.lo)) ||
                glm::any(glm::greaterThan(origin, node.hi))) {
                continue;
            }
            if (node.count == 0) {
                stack[top++] = node.first;
                stack[top++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
                continue;
            }
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const TriangleRecord& tri = triangles_[i];
                const double leaving = glm::dot(tri.normal, direction);
                if (tri.facet == from_facet || leaving <= steepest) continue;
                if (std::abs(glm::dot(tri.normal, origin - tri.v0)) > epsilon_) continue;
                if (!within(tri.normal, tri.v0, tri.v1, origin) ||
                    !within(tri.normal, tri.v1, tri.v2, origin) ||
                    !within(tri.normal, tri.v2, tri.v0, origin)) {
                    continue;
                }
                steepest = leaving;
                best = tri.facet;
            }
        }
        if (best == kNoFacet) return false;
        hit.t = 0.0;
        hit.point = origin;
        hit.facet = best;
        return true;
    }

    // p is no further than epsilon outside the triangle edge a→b (counter-clockwise about n).
    bool within(const glm::dvec3& n, const glm::dvec3& a, const glm::dvec3& b,
                const glm::dvec3& p) const {
        const glm::dvec3 inward = glm::cross(n, b - a);
        return glm::dot(p - a, inward) >= -epsilon_ * glm::length(inward);
    }

    std::vector<BvhNode> nodes_;
    std::vector<TriangleRecord> triangles_;
    double epsilon_ = 0.0;
};

}  // namespace

std::unique_ptr<Intersector> make_bvh_intersector(const Stone& stone) {
    return std::make_unique<BvhIntersector>(stone);
}

}  // namespace gem
