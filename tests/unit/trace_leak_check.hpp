#pragma once
// The no-leak check shared by the leak tests: rays aimed exactly at vertices, at points on
// edges and inside triangles must, once they enter, find an exit on the surface. Only entry
// and first exit are traced (that is where a crack would show), so a million rays are quick.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "optics/fresnel.hpp"
#include "trace/intersector.hpp"
#include "trace_test_stones.hpp"

namespace gem::test {

// The triangles of each facet.
inline std::vector<std::vector<MeshTriangle>> triangles_by_facet(const Stone& s) {
    std::vector<std::vector<MeshTriangle>> by_facet(s.facets.size());
    for (const MeshTriangle& tri : s.triangles) by_facet[tri.facet].push_back(tri);
    return by_facet;
}

// True when p lies on facet `f` within tol: on its plane and inside one of its triangles.
inline bool on_facet(const Stone& s, const std::vector<std::vector<MeshTriangle>>& by_facet,
                     std::uint32_t f, const glm::dvec3& p, double tol) {
    const Plane& plane = s.facets[f].plane;
    if (std::abs(plane.signed_distance(p)) > tol) return false;
    for (const MeshTriangle& tri : by_facet[f]) {
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
            const glm::dvec3 a = s.vertices[tri.v[k]], b = s.vertices[tri.v[(k + 1) % 3]];
            // Distance of p to the inner side of edge ab, within the facet plane.
            const glm::dvec3 inward = glm::normalize(glm::cross(plane.n, b - a));
            inside = glm::dot(p - a, inward) >= -tol;
        }
        if (inside) return true;
    }
    return false;
}

struct LeakStats {
    int entered = 0;
    int lost = 0;         // entered but no exit found
    int not_finite = 0;   // NaN or infinity anywhere
    int off_surface = 0;  // exit point not on its facet
};

inline LeakStats shoot_for_leaks(const Stone& stone, const Intersector& surface, int rays,
                                 double ior, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const double size = bounding_diagonal(stone);
    const double tol = 1e-9 * size;
    const auto by_facet = triangles_by_facet(stone);
    LeakStats stats;
    for (int i = 0; i < rays; ++i) {
        const glm::dvec3 target = random_surface_target(stone, rng, i);
        const glm::dvec3 d = random_unit(rng);
        const glm::dvec3 o = target - 2.0 * size * d;
        SurfaceHit entry;
        if (!surface.next_entry(o, d, kNoFacet, entry)) continue;
        ++stats.entered;
        const glm::dvec3& n = stone.facets[entry.facet].plane.n;
        const auto inside = refract(d, n, 1.0, ior);
        SurfaceHit exit;
        if (!inside || !surface.next_exit(entry.point, *inside, entry.facet, exit)) {
            ++stats.lost;
            continue;
        }
        const bool finite = std::isfinite(exit.t) && std::isfinite(exit.point.x) &&
                            std::isfinite(exit.point.y) && std::isfinite(exit.point.z);
        if (!finite) {
            ++stats.not_finite;
            continue;
        }
        if (!on_facet(stone, by_facet, exit.facet, exit.point, tol)) ++stats.off_surface;
    }
    return stats;
}

inline void expect_no_leaks(const Stone& stone, const Intersector& surface, int rays, double ior,
                            std::uint64_t seed) {
    const LeakStats s = shoot_for_leaks(stone, surface, rays, ior, seed);
    EXPECT_GT(s.entered, rays / 10) << stone.name;
    EXPECT_EQ(s.lost, 0) << stone.name;
    EXPECT_EQ(s.not_finite, 0) << stone.name;
    EXPECT_EQ(s.off_surface, 0) << stone.name;
}

}  // namespace gem::test
