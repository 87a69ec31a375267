#pragma once
// Watertight ray/triangle intersection after Woop, Benthin & Wald, "Watertight Ray/Triangle
// Intersection", Journal of Computer Graphics Techniques 2(1), 2013. The ray is sheared so it
// runs along +z from the origin; the triangle's 2D edge functions U, V, W are then computed
// from the same vertex values for every triangle that shares an edge, so a ray through an edge
// or a vertex is counted by at least one of the triangles around it (no cracks). Zero edge
// functions count as inside. Everything is in double, so the paper's float-to-double fallback
// for exactly-zero edge functions has no counterpart here.

#include <utility>

#include <glm/glm.hpp>

namespace gem {

// Per-ray constants of the shear (the paper's kx, ky, kz and Sx, Sy, Sz).
struct ShearedRay {
    glm::dvec3 origin{0.0};
    int kx = 0, ky = 1, kz = 2;
    double sx = 0.0, sy = 0.0, sz = 1.0;

    ShearedRay(const glm::dvec3& o, const glm::dvec3& d) : origin(o) {
        const glm::dvec3 a = glm::abs(d);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        // Keeps the triangles' winding in the sheared frame (signs of U, V, W).
        if (d[kz] < 0.0) std::swap(kx, ky);
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1.0 / d[kz];
    }
};

// Distance along the ray to the triangle, or false when the ray misses it or lies in its plane.
inline bool intersect_watertight(const ShearedRay& r, const glm::dvec3& v0, const glm::dvec3& v1,
                                 const glm::dvec3& v2, double& t) {
    const glm::dvec3 a = v0 - r.origin;
    const glm::dvec3 b = v1 - r.origin;
    const glm::dvec3 c = v2 - r.origin;
    const double ax = a[r.kx] - r.sx * a[r.kz];
    const double ay = a[r.ky] - r.sy * a[r.kz];
    const double bx = b[r.kx] - r.sx * b[r.kz];
    const double by = b[r.ky] - r.sy * b[r.kz];
    const double cx = c[r.kx] - r.sx * c[r.kz];
    const double cy = c[r.ky] - r.sy * c[r.kz];
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    const double det = u + v + w;
    if (det == 0.0) return false;
    const double az = r.sz * a[r.kz];
    const double bz = r.sz * b[r.kz];
    const double cz = r.sz * c[r.kz];
    t = (u * az + v * bz + w * cz) / det;
    return true;
}

}  // namespace gem
