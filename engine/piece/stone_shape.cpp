#include "piece/stone_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trace/ray_triangle.hpp"

namespace gem {

namespace {

bool inside(const Stone& stone, const glm::dvec3& p) {
    if (stone.convex) {
        for (const Facet& f : stone.facets) {
            if (f.plane.signed_distance(p) > 0.0) return false;
        }
        return true;
    }
    // Crossings along a direction no facet of a cut lies along.
    const ShearedRay ray(p, glm::normalize(glm::dvec3(0.3127, 0.8011, 0.5101)));
    int crossings = 0;
    for (const MeshTriangle& t : stone.triangles) {
        double d = 0.0;
        if (intersect_watertight(ray, stone.vertices[t.v[0]], stone.vertices[t.v[1]],
                                 stone.vertices[t.v[2]], d) &&
            d > 0.0) {
            ++crossings;
        }
    }
    return crossings % 2 == 1;
}

}  // namespace

// The closest point to p on triangle abc (Ericson, "Real-Time Collision Detection", 5.1.5:
// the Voronoi regions of the vertices, then the edges, then the face).
glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                               const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

Stone scaled_stone(Stone stone, double factor) {
    for (glm::dvec3& v : stone.vertices) v *= factor;
    for (Facet& f : stone.facets) f.plane.d *= factor;
    return stone;
}

StoneExtent stone_extent(const Stone& stone) {
    StoneExtent e;
    e.table_y = -std::numeric_limits<double>::infinity();
    e.culet_y = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& v : stone.vertices) {
        e.girdle_radius = std::max(e.girdle_radius, std::hypot(v.x, v.z));
        e.table_y = std::max(e.table_y, v.y);
        e.culet_y = std::min(e.culet_y, v.y);
    }
    e.girdle_top = e.culet_y;
    e.girdle_bottom = e.table_y;
    for (const glm::dvec3& v : stone.vertices) {
        if (std::hypot(v.x, v.z) > 0.97 * e.girdle_radius) {
            e.girdle_top = std::max(e.girdle_top, v.y);
            e.girdle_bottom = std::min(e.girdle_bottom, v.y);
        }
    }
    return e;
}

double girdle_width(const Stone& stone) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec3& v : stone.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return std::min(hi.x - lo.x, hi.z - lo.z);
}

Stone stone_at_width(Stone stone, double width_mm) {
    const double factor = width_mm / girdle_width(stone);
    return scaled_stone(std::move(stone), factor);
}

double outline_radius(const Stone& stone, const glm::dvec3& u) {
    const ShearedRay ray(glm::dvec3(0.0), u);
    double far = 0.0;
    for (const MeshTriangle& t : stone.triangles) {
        double d = 0.0;
        if (intersect_watertight(ray, stone.vertices[t.v[0]], stone.vertices[t.v[1]],
                                 stone.vertices[t.v[2]], d)) {
            far = std::max(far, d);
        }
    }
    return far;
}

glm::dvec3 closest_point(const Stone& stone, const glm::dvec3& p) {
    double d2 = std::numeric_limits<double>::infinity();
    glm::dvec3 best = p;
    for (const MeshTriangle& t : stone.triangles) {
        const glm::dvec3 q = closest_on_triangle(p, stone.vertices[t.v[0]], stone.vertices[t.v[1]],
                                                 stone.vertices[t.v[2]]);
        if (const double e = glm::dot(p - q, p - q); e < d2) {
            d2 = e;
            best = q;
        }
    }
    return best;
}

double signed_distance(const Stone& stone, const glm::dvec3& p) {
    const double d = glm::length(p - closest_point(stone, p));
    return inside(stone, p) ? -d : d;
}

}  // namespace gem
