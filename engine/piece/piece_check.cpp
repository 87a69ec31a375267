#include "piece/piece_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "geometry/stone.hpp"
#include "piece/seat.hpp"
#include "piece/stone_shape.hpp"
#include "trace/ray_triangle.hpp"

namespace gem {

namespace {

// Whether an edge of `a` crosses the surface of `b` (b's frame), or a's first vertex lies
// inside b.
bool crosses(const Stone& a, const Placement& pa, const Stone& b, const Placement& pb) {
    auto in_b = [&](const glm::dvec3& p) { return pb.to_stone(pa.to_piece(p)); };
    if (signed_distance(b, in_b(a.vertices.front())) < -1e-9) return true;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const MeshTriangle& t : a.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = t.v[k], v = t.v[(k + 1) % 3];
            edges.insert({std::min(u, v), std::max(u, v)});
        }
    }
    for (const auto& [u, v] : edges) {
        const glm::dvec3 p = in_b(a.vertices[u]), q = in_b(a.vertices[v]);
        const double length = glm::length(q - p);
        if (!(length > 0.0)) continue;
        const ShearedRay ray(p, (q - p) / length);
        for (const MeshTriangle& t : b.triangles) {
            double d = 0.0;
            if (intersect_watertight(ray, b.vertices[t.v[0]], b.vertices[t.v[1]],
                                     b.vertices[t.v[2]], d) &&
                d > 1e-9 && d < length - 1e-9) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace

bool stones_intersect(const Stone& a, const Placement& pa, const Stone& b, const Placement& pb) {
    if (glm::length(pa.position - pb.position) >
        bounding_radius(a.vertices) + bounding_radius(b.vertices))
        return false;
    return crosses(a, pa, b, pb) || crosses(b, pb, a, pa);
}

Result<bool> check_piece(const Piece& piece, double rounding_mm) {
    const std::vector<PieceProblem> problems = piece_problems(piece, rounding_mm);
    if (!problems.empty()) return Error{problems.front().message};
    return true;
}

std::vector<PieceProblem> piece_problems(const Piece& piece, double rounding_mm) {
    using Kind = PieceProblem::Kind;
    std::vector<PieceProblem> problems;
    const double seat = kSeatMm + rounding_mm, held = kHeldMm + rounding_mm;
    auto name = [&](std::size_t i) {
        return "stone " + std::to_string(i + 1) + " ('" + piece.stones[i].role + "')";
    };
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        for (std::size_t j = i + 1; j < piece.stones.size(); ++j) {
            if (stones_intersect(piece.stone_of(i), piece.stones[i].placement, piece.stone_of(j),
                                 piece.stones[j].placement)) {
                problems.push_back({Kind::stones_intersect, name(j) + " intersects " + name(i)});
            }
        }
    }
    // Each stone against the metal near it: the nearest metal must touch it, and nothing may
    // cut deeper than a seat, neither metal into the stone nor the stone into the metal.
    const MetalMesh& metal = piece.metal;
    // Each metal triangle's centre and reach, once in the piece's frame: a stone then skips
    // the triangles far from it without taking them into its own frame.
    std::vector<glm::dvec4> spheres(metal.indices.size() / 3);
    for (std::size_t t = 0; t < spheres.size(); ++t) {
        const glm::dvec3 a(metal.positions[metal.indices[3 * t]]);
        const glm::dvec3 b(metal.positions[metal.indices[3 * t + 1]]);
        const glm::dvec3 c(metal.positions[metal.indices[3 * t + 2]]);
        const glm::dvec3 mid = (a + b + c) / 3.0;
        spheres[t] = glm::dvec4(
            mid, std::max({glm::length(a - mid), glm::length(b - mid), glm::length(c - mid)}));
    }
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        const Stone& stone = piece.stone_of(i);
        const Placement& place = piece.stones[i].placement;
        const double reach = bounding_radius(stone.vertices) + held;
        double nearest = std::numeric_limits<double>::infinity();
        double deepest = 0.0;
        for (const glm::vec3& v : metal.positions) {
            // A placement is rigid: the distance from the stone's centre is frame-free.
            if (glm::length(glm::dvec3(v) - place.position) > reach) continue;
            const glm::dvec3 p = place.to_stone(glm::dvec3(v));
            const double d = signed_distance(stone, p);
            nearest = std::min(nearest, d);
            deepest = std::max(deepest, -d);
        }
        // The stone's corners against the metal's faces near it. A corner is inside the metal
        // when the face nearest to it faces away from it and its nearest point lies inside that
        // face (at an edge or a corner of the metal the side is not decided, and it counts as
        // outside); the faces' outward side is where their vertex normals point.
        std::vector<double> corner_distance(stone.vertices.size(),
                                            std::numeric_limits<double>::infinity());
        std::vector<char> corner_inside(stone.vertices.size(), 0);
        for (std::size_t t = 0; t + 2 < metal.indices.size(); t += 3) {
            const glm::dvec4& sphere = spheres[t / 3];
            if (glm::length(glm::dvec3(sphere) - place.position) > reach + sphere.w) continue;
            const glm::dvec3 a = place.to_stone(glm::dvec3(metal.positions[metal.indices[t]]));
            const glm::dvec3 b = place.to_stone(glm::dvec3(metal.positions[metal.indices[t + 1]]));
            const glm::dvec3 c = place.to_stone(glm::dvec3(metal.positions[metal.indices[t + 2]]));
            const glm::dvec3 mid = (a + b + c) / 3.0;
            const double size =
                std::max({glm::length(a - mid), glm::length(b - mid), glm::length(c - mid)});
            if (glm::length(mid) > reach + size) continue;
            glm::dvec3 n = glm::cross(b - a, c - a);
            const glm::dvec3 normals = place.direction_to_stone(
                glm::dvec3(metal.normals[metal.indices[t]] + metal.normals[metal.indices[t + 1]] +
                           metal.normals[metal.indices[t + 2]]));
            if (glm::dot(n, normals) < 0.0) n = -n;
            const double area2 = glm::dot(n, n);
            if (!(area2 > 0.0)) continue;
            for (std::size_t k = 0; k < stone.vertices.size(); ++k) {
                const glm::dvec3& v = stone.vertices[k];
                const glm::dvec3 q = closest_on_triangle(v, a, b, c);
                const double d = glm::length(v - q);
                if (!(d < corner_distance[k])) continue;
                corner_distance[k] = d;
                // Inside the face: q is v's projection onto the face's plane.
                const glm::dvec3 projected = v - glm::dot(v - a, n) / area2 * n;
                const bool interior = glm::length(projected - q) < 1e-9;
                corner_inside[k] = interior && glm::dot(v - q, n) < 0.0;
            }
        }
        for (std::size_t k = 0; k < stone.vertices.size(); ++k) {
            nearest = std::min(nearest, corner_distance[k]);
            if (corner_inside[k]) deepest = std::max(deepest, corner_distance[k]);
        }
        if (deepest > seat + 1e-6) {
            problems.push_back({Kind::metal_cuts_in, "the metal cuts " + std::to_string(deepest) +
                                                         " mm into " + name(i) +
                                                         " (a seat is at most " +
                                                         std::to_string(seat) + " mm)"});
        } else if (!(nearest <= held)) {
            problems.push_back({Kind::stone_floats,
                                name(i) + " floats off its seat: the nearest metal is " +
                                    (std::isfinite(nearest) ? std::to_string(nearest) + " mm away"
                                                            : std::string("beyond the stone")) +
                                    " (at most " + std::to_string(held) + " mm)"});
        }
    }
    return problems;
}

}  // namespace gem
