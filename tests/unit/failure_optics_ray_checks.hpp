#pragma once
// Checks of one traced ray against the stone's geometry, independent of the tracer's own
// bookkeeping: the internal reflection chain is followed again here, segment by segment,
// through the intersector (the part that could leak), and every exit the tracer recorded must
// sit on that chain, on the solid, and obey Snell's law in its vector form
// n₁ (d₁ × N) = n₂ (d₂ × N) (Born & Wolf §1.5.1).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "failure_optics_support.hpp"
#include "optics/fresnel.hpp"
#include "trace/intersector.hpp"

namespace gem::failure_test {

struct RayCheck {
    int traced = 0;     // rays that hit the stone
    int bad = 0;        // a non-finite number, energy off 1, or an exit off the chain
    int lost = 0;       // the chain found no exit from inside the solid (a leak)
    int off_solid = 0;  // a chain point outside some facet plane
    int snell = 0;      // exits checked against Snell's law
};

// Largest signed distance of p outside the stone's facet planes (≤ 0 inside).
inline double outside_by(const Stone& stone, const glm::dvec3& p) {
    double worst = -1e300;
    for (const Facet& f : stone.facets) worst = std::max(worst, f.plane.signed_distance(p));
    return worst;
}

// Traces `ray` into a convex stone with depth `depth` and no weight threshold and checks it.
inline void check_ray(const Stone& stone, const Tracer& tracer, const Intersector& surface,
                      const Ray& ray, double n, int depth, RayCheck& out) {
    TraceSettings settings;
    settings.max_depth = depth;
    settings.min_weight = 0.0;
    RayList list;
    tracer.trace(ray, n, settings, list);
    if (!list.hit) return;
    ++out.traced;
    const double tol = 1e-9 * (1.0 + glm::length(list.reflected.origin));
    if (!all_finite(list) || std::abs(energy(list) - 1.0) > 1e-9) {
        ++out.bad;
        return;
    }
    // The chain: entry point, then each internal hit, with the direction that reached it.
    std::vector<glm::dvec3> point{list.reflected.origin};
    std::vector<glm::dvec3> arriving;
    std::vector<std::uint32_t> facet{list.reflected.facet};
    auto dir = refract(ray.direction, stone.facets[list.reflected.facet].plane.n, 1.0, n);
    if (!dir) return;  // grazing entry: nothing goes in
    for (int k = 0; k < depth; ++k) {
        SurfaceHit hit;
        if (!surface.next_exit(point.back(), *dir, facet.back(), hit)) {
            ++out.lost;
            return;
        }
        if (outside_by(stone, hit.point) > tol) ++out.off_solid;
        point.push_back(hit.point);
        arriving.push_back(*dir);
        facet.push_back(hit.facet);
        dir = reflect(*dir, stone.facets[hit.facet].plane.n);
    }
    for (const TracedRay& e : list.exits) {
        const std::size_t k = e.bounces + 1u;  // left at the (bounces + 1)-th internal hit
        if (k >= point.size() || glm::length(e.origin - point[k]) > tol || e.facet != facet[k]) {
            ++out.bad;
            continue;
        }
        const glm::dvec3& normal = stone.facets[e.facet].plane.n;
        const glm::dvec3 lhs = n * glm::cross(arriving[k - 1], normal);
        const glm::dvec3 rhs = 1.0 * glm::cross(e.direction, normal);
        if (glm::length(lhs - rhs) > 1e-9 || glm::dot(e.direction, normal) <= 0.0) ++out.bad;
        ++out.snell;
    }
}

inline void expect_clean(const RayCheck& c, const std::string& what, int min_traced) {
    EXPECT_GE(c.traced, min_traced) << what;
    EXPECT_EQ(c.bad, 0) << what;
    EXPECT_EQ(c.lost, 0) << what;
    EXPECT_EQ(c.off_solid, 0) << what;
    EXPECT_GT(c.snell, 0) << what;
}

// Targets around p: p itself and p moved by one ulp up and down in each coordinate.
inline std::vector<glm::dvec3> ulp_neighbourhood(const glm::dvec3& p) {
    std::vector<glm::dvec3> out{p};
    for (int a = 0; a < 3; ++a) {
        for (double toward : {-1e300, 1e300}) {
            glm::dvec3 q = p;
            q[a] = std::nextafter(q[a], toward);
            out.push_back(q);
        }
    }
    return out;
}

}  // namespace gem::failure_test
