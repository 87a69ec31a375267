#pragma once
// Hand-built stones for the tracer tests, with geometry known by construction: a box (convex)
// and a star-shaped prism (non-convex, with reflex edges a ray can leave and re-enter by).
// Facet planes come from the construction, not from code under test.

#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"

namespace gem::test {

// Adds a planar face with its outward normal; triangles fan from loop[0] (convex faces) or,
// when `centre` is given, from that extra vertex (star-shaped faces).
inline void add_face(Stone& stone, const std::vector<std::uint32_t>& loop, glm::dvec3 normal,
                     FacetKind kind, const glm::dvec3* centre = nullptr) {
    const auto facet = static_cast<std::uint32_t>(stone.facets.size());
    normal = glm::normalize(normal);
    stone.facets.push_back({{normal, glm::dot(normal, stone.vertices[loop[0]])}, loop, kind, ""});
    if (centre) {
        const auto c = static_cast<std::uint32_t>(stone.vertices.size());
        stone.vertices.push_back(*centre);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            stone.triangles.push_back({{c, loop[i], loop[(i + 1) % loop.size()]}, facet});
        }
        return;
    }
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        stone.triangles.push_back({{loop[0], loop[i], loop[i + 1]}, facet});
    }
}

// Axis-aligned box [-hx,hx]×[-hy,hy]×[-hz,hz]; facets in the order +x, -x, +y, -y, +z, -z.
inline Stone box_stone(double hx, double hy, double hz) {
    Stone s;
    s.name = "box";
    for (int i = 0; i < 8; ++i) {
        s.vertices.push_back({i & 1 ? hx : -hx, i & 2 ? hy : -hy, i & 4 ? hz : -hz});
    }
    // Vertex index bits: 1 = +x, 2 = +y, 4 = +z; loops counter-clockwise seen from outside.
    add_face(s, {1, 3, 7, 5}, {1, 0, 0}, FacetKind::other);
    add_face(s, {0, 4, 6, 2}, {-1, 0, 0}, FacetKind::other);
    add_face(s, {2, 6, 7, 3}, {0, 1, 0}, FacetKind::table);
    add_face(s, {0, 1, 5, 4}, {0, -1, 0}, FacetKind::culet);
    add_face(s, {4, 5, 7, 6}, {0, 0, 1}, FacetKind::other);
    add_face(s, {0, 2, 3, 1}, {0, 0, -1}, FacetKind::other);
    s.convex = true;
    return s;
}

// A prism over a star polygon with `points` tips (radius r_tip) and notches (radius r_notch)
// in the xz plane, from y = -h to y = +h. Non-convex for r_notch < r_tip · cos(π / points).
inline Stone star_prism_stone(int points, double r_tip, double r_notch, double h) {
    Stone s;
    s.name = "star prism";
    const int n = 2 * points;
    for (int k = 0; k < n; ++k) {
        const double a = std::numbers::pi * k / points;
        const double r = k % 2 == 0 ? r_tip : r_notch;
        // Angle runs from +x toward -z so that the loop is counter-clockwise seen from +y.
        s.vertices.push_back({r * std::cos(a), -h, -r * std::sin(a)});
        s.vertices.push_back({r * std::cos(a), h, -r * std::sin(a)});
    }
    std::vector<std::uint32_t> top, bottom;
    for (int k = 0; k < n; ++k) top.push_back(static_cast<std::uint32_t>(2 * k + 1));
    for (int k = n - 1; k >= 0; --k) bottom.push_back(static_cast<std::uint32_t>(2 * k));
    const glm::dvec3 top_centre{0, h, 0}, bottom_centre{0, -h, 0};
    add_face(s, top, {0, 1, 0}, FacetKind::table, &top_centre);
    add_face(s, bottom, {0, -1, 0}, FacetKind::culet, &bottom_centre);
    for (int k = 0; k < n; ++k) {
        const auto lo0 = static_cast<std::uint32_t>(2 * k);
        const auto lo1 = static_cast<std::uint32_t>(2 * ((k + 1) % n));
        const glm::dvec3 edge = s.vertices[lo1] - s.vertices[lo0];
        add_face(s, {lo0, lo1, lo1 + 1, lo0 + 1}, glm::cross(edge, glm::dvec3(0, 1, 0)),
                 FacetKind::girdle);
    }
    s.convex = false;
    return s;
}

inline glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const glm::dvec3 v{g(rng), g(rng), g(rng)};
        const double len = glm::length(v);
        if (len > 1e-6) return v / len;
    }
}

inline double bounding_diagonal(const Stone& s) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& v : s.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return glm::length(hi - lo);
}

// A point on the surface: a vertex, a point on a triangle edge, or inside a triangle, in turn,
// so that rays aimed at it go exactly through vertices and edges a third of the time each.
inline glm::dvec3 random_surface_target(const Stone& s, std::mt19937_64& rng, int kind) {
    std::uniform_int_distribution<std::size_t> pick(0, s.triangles.size() - 1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const MeshTriangle& tri = s.triangles[pick(rng)];
    const glm::dvec3 a = s.vertices[tri.v[0]], b = s.vertices[tri.v[1]], c = s.vertices[tri.v[2]];
    switch (kind % 3) {
        case 0:
            return a;
        case 1:
            return glm::mix(a, b, u(rng));
        default: {
            double x = u(rng), y = u(rng);
            if (x + y > 1.0) x = 1.0 - x, y = 1.0 - y;
            return a + x * (b - a) + y * (c - a);
        }
    }
}

}  // namespace gem::test
