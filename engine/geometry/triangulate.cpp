// Ear clipping: triangulates simple polygons, convex or not (a heart's notched table, an
// imported star-shaped face).

#include "geometry/triangulate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace gem {
namespace {

// A basis (u, v) of the plane with u × v = n, so counter-clockwise in (u, v) is
// counter-clockwise seen from outside.
std::pair<glm::dvec3, glm::dvec3> plane_basis(const glm::dvec3& n) {
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
    return {u, glm::cross(n, u)};
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
    return a.x * b.y - a.y * b.x;
}

bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                     const glm::dvec2& c) {
    return cross2(b - a, p - a) >= 0.0 && cross2(c - b, p - b) >= 0.0 &&
           cross2(a - c, p - c) >= 0.0;
}

}  // namespace

glm::dvec3 newell_normal(const std::vector<glm::dvec3>& vertices,
                         const std::vector<std::uint32_t>& loop) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < loop.size(); ++i) {
        n += glm::cross(vertices[loop[i]], vertices[loop[(i + 1) % loop.size()]]);
    }
    return n;
}

void triangulate_polygon(const std::vector<glm::dvec3>& vertices,
                         const std::vector<std::uint32_t>& loop, const glm::dvec3& normal,
                         std::vector<std::array<std::uint32_t, 3>>& out) {
    if (loop.size() < 3) return;
    const auto [u, v] = plane_basis(glm::normalize(normal));
    std::vector<glm::dvec2> p;
    double extent = 0.0;
    for (std::uint32_t i : loop) {
        p.emplace_back(glm::dot(vertices[i], u), glm::dot(vertices[i], v));
        extent = std::max(extent, glm::length(p.back() - p.front()));
    }
    const double min_area = 1e-14 * extent * extent;
    std::vector<std::size_t> left(p.size());
    for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;

    auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
        out.push_back({loop[a], loop[b], loop[c]});
    };
    while (left.size() > 3) {
        const std::size_t m = left.size();
        std::optional<std::size_t> ear;
        std::size_t flattest = 0;
        double flattest_area = -INFINITY;
        for (std::size_t k = 0; k < m && !ear; ++k) {
            const std::size_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
            const double area = cross2(p[b] - p[a], p[c] - p[b]);
            if (area > flattest_area) flattest_area = area, flattest = k;
            if (area <= min_area) continue;  // reflex or flat: not an ear
            bool blocked = false;
            for (std::size_t j : left) {
                if (j == a || j == b || j == c || p[j] == p[a] || p[j] == p[b] || p[j] == p[c]) {
                    continue;
                }
                if (inside_triangle(p[j], p[a], p[b], p[c])) {
                    blocked = true;
                    break;
                }
            }
            if (!blocked) ear = k;
        }
        // A valid simple polygon always has an ear; the fallback only guards against
        // round-off on nearly degenerate loops.
        const std::size_t k = ear.value_or(flattest);
        emit(left[(k + m - 1) % m], left[k], left[(k + 1) % m]);
        left.erase(left.begin() + std::ptrdiff_t(k));
    }
    if (left.size() == 3 && cross2(p[left[1]] - p[left[0]], p[left[2]] - p[left[1]]) > 0.0) {
        emit(left[0], left[1], left[2]);
    }
}

}  // namespace gem
