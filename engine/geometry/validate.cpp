// Solid checks. Tolerances are relative to the stone's size (its bounding-box diagonal), so
// the same default works for a 1 mm melee and a 30 mm display stone.

#include "geometry/validate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace gem {
namespace {

constexpr std::size_t kMaxReportedPerCheck = 5;

double stone_size(const Stone& stone) {
    if (stone.vertices.empty()) return 0.0;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& v : stone.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return glm::length(hi - lo);
}

std::string facet_label(const Stone& stone, std::size_t f) {
    std::string label = "facet " + std::to_string(f);
    if (!stone.facets[f].name.empty()) label += " (" + stone.facets[f].name + ")";
    return label;
}

// Adds a problem unless `count` already reached the limit, so a badly broken mesh gives a
// readable report instead of thousands of lines.
void report(std::vector<std::string>& problems, std::size_t& count, std::string text) {
    if (count++ < kMaxReportedPerCheck) problems.push_back(std::move(text));
}

void check_edges(const Stone& stone, SolidReport& r) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::set<std::pair<std::uint32_t, std::uint32_t>> undirected;
    std::set<std::uint32_t> used;
    for (const Facet& facet : stone.facets) {
        for (std::size_t i = 0; i < facet.loop.size(); ++i) {
            const std::uint32_t a = facet.loop[i];
            const std::uint32_t b = facet.loop[(i + 1) % facet.loop.size()];
            ++directed[{a, b}];
            undirected.insert(std::minmax(a, b));
            used.insert(a);
        }
    }
    r.euler_characteristic =
        int(stone.vertices.size()) - int(undirected.size()) + int(stone.facets.size());
    std::size_t count = 0;
    if (used.size() != stone.vertices.size()) {
        report(r.problems, count,
               std::to_string(stone.vertices.size() - used.size()) + " vertices are unused");
    }
    for (const auto& [edge, uses] : directed) {
        const auto back = directed.find({edge.second, edge.first});
        const int reverse_uses = back == directed.end() ? 0 : back->second;
        if (uses != 1 || reverse_uses != 1) {
            report(r.problems, count,
                   "edge " + std::to_string(edge.first) + "->" + std::to_string(edge.second) +
                       " is used " + std::to_string(uses) + " time(s) and reversed " +
                       std::to_string(reverse_uses) + " time(s); expected once each");
        }
    }
    r.closed = count == 0;
}

void check_facets(const Stone& stone, double tol, SolidReport& r) {
    std::size_t flat_count = 0;
    std::size_t out_count = 0;
    for (std::size_t f = 0; f < stone.facets.size(); ++f) {
        const Facet& facet = stone.facets[f];
        if (facet.loop.size() < 3) {
            report(r.problems, out_count, facet_label(stone, f) + " has fewer than 3 vertices");
            continue;
        }
        if (std::abs(glm::length(facet.plane.n) - 1.0) > 1e-9) {
            report(r.problems, flat_count, facet_label(stone, f) + " has a non-unit normal");
        }
        glm::dvec3 newell(0.0);
        for (std::size_t i = 0; i < facet.loop.size(); ++i) {
            const glm::dvec3& p = stone.vertices[facet.loop[i]];
            newell += glm::cross(p, stone.vertices[facet.loop[(i + 1) % facet.loop.size()]]);
            const double off = std::abs(facet.plane.signed_distance(p));
            if (off > tol) {
                report(r.problems, flat_count,
                       facet_label(stone, f) + ": vertex " + std::to_string(facet.loop[i]) +
                           " is " + std::to_string(off) + " mm off the facet plane");
            }
        }
        if (glm::dot(newell, facet.plane.n) <= 0.0) {
            report(r.problems, out_count,
                   facet_label(stone, f) + " is wound clockwise seen from outside");
        }
    }
    r.planar = flat_count == 0;
    r.outward = out_count == 0;
}

void measure_triangles(const Stone& stone, double tol, SolidReport& r) {
    std::size_t count = 0;
    for (const MeshTriangle& t : stone.triangles) {
        if (t.facet >= stone.facets.size() ||
            std::any_of(t.v.begin(), t.v.end(),
                        [&](std::uint32_t v) { return v >= stone.vertices.size(); })) {
            report(r.problems, count, "a triangle refers to a missing vertex or facet");
            continue;
        }
        const glm::dvec3& a = stone.vertices[t.v[0]];
        const glm::dvec3& b = stone.vertices[t.v[1]];
        const glm::dvec3& c = stone.vertices[t.v[2]];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        r.volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        r.area += 0.5 * glm::length(n);
        if (glm::dot(n, stone.facets[t.facet].plane.n) < 0.0) {
            report(r.problems, count,
                   "a triangle of " + facet_label(stone, t.facet) + " is wound against its facet");
        }
    }
    // The triangles must cover the facets exactly: compare with the loops' own areas.
    double loop_area = 0.0;
    for (const Facet& facet : stone.facets) {
        glm::dvec3 newell(0.0);
        for (std::size_t i = 0; i < facet.loop.size(); ++i) {
            newell += glm::cross(stone.vertices[facet.loop[i]],
                                 stone.vertices[facet.loop[(i + 1) % facet.loop.size()]]);
        }
        loop_area += 0.5 * glm::length(newell);
    }
    if (std::abs(loop_area - r.area) > 1e-8 * loop_area + tol * tol) {
        report(r.problems, count,
               "triangles cover " + std::to_string(r.area) + " mm² but the facets " +
                   std::to_string(loop_area) + " mm²");
    }
    if (r.volume <= 0.0) {
        report(r.problems, count,
               "volume is " + std::to_string(r.volume) + " mm³; expected a positive value");
    }
}

}  // namespace

SolidReport check_solid(const Stone& stone, double tolerance) {
    SolidReport r;
    if (stone.vertices.empty() || stone.facets.empty()) {
        r.problems.push_back("the stone has no vertices or no facets");
        return r;
    }
    const double tol = tolerance * stone_size(stone);
    check_edges(stone, r);
    check_facets(stone, tol, r);
    measure_triangles(stone, tol, r);
    if (r.euler_characteristic != 2) {
        r.problems.push_back("Euler characteristic V-E+F is " +
                             std::to_string(r.euler_characteristic) + "; expected 2");
    }
    return r;
}

int gemmological_facet_count(const Stone& stone) {
    return int(std::count_if(stone.facets.begin(), stone.facets.end(),
                             [](const Facet& f) { return f.kind != FacetKind::girdle; }));
}

bool symmetry_holds(const Stone& stone, double tolerance) {
    const double tol = tolerance * stone_size(stone);
    for (const glm::dmat3& m : stone.symmetry) {
        for (const glm::dvec3& v : stone.vertices) {
            const glm::dvec3 image = m * v;
            const bool found =
                std::any_of(stone.vertices.begin(), stone.vertices.end(),
                            [&](const glm::dvec3& w) { return glm::length(image - w) <= tol; });
            if (!found) return false;
        }
    }
    return true;
}

}  // namespace gem
