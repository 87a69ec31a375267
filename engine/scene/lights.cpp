#include "scene/lights.hpp"

#include <cmath>
#include <limits>

namespace gem {

glm::dvec3 direction_to_light(const Light& light, const glm::dvec3& p) {
    return glm::normalize(light.directional ? light.position : light.position - p);
}

double specular_lobe(const glm::dvec3& ray_direction, const glm::dvec3& to_light, double h) {
    const double c = glm::dot(ray_direction, to_light);
    return c > 0.0 ? std::pow(c, h) : 0.0;
}

namespace {

// Möller & Trumbore, "Fast, minimum storage ray/triangle intersection" (1997); returns the
// ray parameter of a hit in front of the origin, or infinity.
double hit_distance(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                    const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a;
    const glm::dvec3 e2 = c - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (std::abs(det) < 1e-15) return kNone;
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return kNone;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return kNone;
    const double t = glm::dot(e2, q) * inv;
    return t > 0.0 ? t : kNone;
}

}  // namespace

bool light_blocked(const Stone& stone, const glm::dvec3& p, std::uint32_t facet, const Light& light,
                   const glm::dvec3& to_light) {
    assert(facet < stone.facets.size());
    const Plane& plane = stone.facets[facet].plane;
    if (glm::dot(plane.n, to_light) <= 0.0) return true;
    if (stone.convex) return false;
    // Start a hair off the surface so the leaving facet does not hit itself.
    const glm::dvec3 origin = p + plane.n * 1e-7;
    const double limit = light.directional ? std::numeric_limits<double>::infinity()
                                           : glm::length(light.position - origin);
    for (const MeshTriangle& tri : stone.triangles) {
        const double t = hit_distance(origin, to_light, stone.vertices[tri.v[0]],
                                      stone.vertices[tri.v[1]], stone.vertices[tri.v[2]]);
        if (t < limit) return true;
    }
    return false;
}

}  // namespace gem
