// stone_from_triangles: a closed triangle mesh (OBJ, STL, 3D Studio) becomes a Stone whose
// facets are the groups of edge-connected coplanar triangles.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace gem {
namespace {

using Tri = std::array<std::uint32_t, 3>;

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

struct CellKey {
    std::int64_t x, y, z;
    bool operator==(const CellKey&) const = default;
};

struct CellHash {
    std::size_t operator()(const CellKey& k) const {
        std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
        h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
        h ^= static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
        return static_cast<std::size_t>(h);
    }
};

// Maps every input position to a representative within `tolerance` (first one seen wins), on a
// grid of cells `tolerance` wide so only the 27 neighbouring cells need to be searched.
std::vector<std::uint32_t> weld(const std::vector<glm::dvec3>& positions, double tolerance) {
    std::vector<std::uint32_t> representative(positions.size());
    // Cells counted from the lower corner of the bounding box keep the integer cell numbers
    // in range however far the mesh lies from the origin.
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double span = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 0.0});
    const double cell =
        std::max(tolerance, span * 1e-12) > 0.0 ? std::max(tolerance, span * 1e-12) : 1.0;
    std::unordered_map<CellKey, std::vector<std::uint32_t>, CellHash> grid;
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3& p = positions[i];
        const glm::dvec3 q = glm::floor((p - lo) / cell);
        const CellKey home{static_cast<std::int64_t>(q.x), static_cast<std::int64_t>(q.y),
                           static_cast<std::int64_t>(q.z)};
        std::uint32_t found = i;
        for (int dx = -1; dx <= 1 && found == i; ++dx) {
            for (int dy = -1; dy <= 1 && found == i; ++dy) {
                for (int dz = -1; dz <= 1 && found == i; ++dz) {
                    auto it = grid.find({home.x + dx, home.y + dy, home.z + dz});
                    if (it == grid.end()) continue;
                    for (std::uint32_t j : it->second) {
                        if (glm::length(positions[j] - p) <= tolerance) {
                            found = j;
                            break;
                        }
                    }
                }
            }
        }
        representative[i] = found;
        if (found == i) grid[home].push_back(i);
    }
    return representative;
}

glm::dvec3 area_vector(const std::vector<glm::dvec3>& v, const Tri& t) {
    return glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
}

// The boundary of a triangle group as one closed loop, or empty when it is not a single
// simple cycle (a facet with a hole, or two pieces touching at a vertex).
std::vector<std::uint32_t> boundary_loop(
    const std::vector<std::uint32_t>& group, const std::vector<Tri>& tris,
    const std::vector<std::uint32_t>& group_of,
    const std::unordered_map<std::uint64_t, std::uint32_t>& owner) {
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    for (std::uint32_t t : group) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
            const std::uint32_t other = owner.at(edge_key(b, a));
            if (group_of[other] == group_of[t]) continue;
            if (!next.emplace(a, b).second) return {};
        }
    }
    if (next.empty()) return {};
    std::vector<std::uint32_t> loop;
    const std::uint32_t start = next.begin()->first;
    std::uint32_t at = start;
    do {
        loop.push_back(at);
        auto it = next.find(at);
        if (it == next.end() || loop.size() > next.size()) return {};
        at = it->second;
    } while (at != start);
    if (loop.size() != next.size()) return {};
    return loop;
}

Plane fit_plane(const std::vector<glm::dvec3>& v, const std::vector<Tri>& tris,
                const std::vector<std::uint32_t>& group) {
    glm::dvec3 normal{0.0};
    glm::dvec3 weighted_centroid{0.0};
    double area = 0.0;
    for (std::uint32_t t : group) {
        const glm::dvec3 a = area_vector(v, tris[t]);
        const double w = glm::length(a);
        normal += a;
        weighted_centroid += w * (v[tris[t][0]] + v[tris[t][1]] + v[tris[t][2]]) / 3.0;
        area += w;
    }
    Plane plane;
    plane.n = glm::normalize(normal);
    plane.d = glm::dot(plane.n, weighted_centroid / area);
    return plane;
}

}  // namespace

Result<Stone> stone_from_triangles(const std::vector<glm::dvec3>& positions,
                                   const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                   std::string name, double weld_tolerance,
                                   double planar_tolerance) {
    if (triangles.empty()) return Error{"mesh has no triangles"};
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (std::uint32_t i : triangles[t]) {
            if (i >= positions.size()) {
                return Error{"triangle " + std::to_string(t) + " refers to vertex " +
                             std::to_string(i) + " of " + std::to_string(positions.size())};
            }
        }
    }
    glm::dvec3 lo{HUGE_VAL}, hi{-HUGE_VAL};
    for (const auto& p : positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return Error{"mesh has a vertex that is not a finite number"};
        }
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double size = glm::length(hi - lo);
    if (!(size > 0.0)) return Error{"mesh has no extent (all vertices coincide)"};

    // Weld, then renumber the vertices that triangles use, in order of first use.
    const std::vector<std::uint32_t> rep = weld(positions, weld_tolerance * size);
    constexpr std::uint32_t kUnused = ~0u;
    std::vector<std::uint32_t> new_index(positions.size(), kUnused);
    Stone stone;
    stone.name = std::move(name);
    std::vector<Tri> tris;
    std::vector<std::size_t> source;  // each kept triangle's number in the input, for messages
    tris.reserve(triangles.size());
    for (std::size_t n = 0; n < triangles.size(); ++n) {
        const auto& in = triangles[n];
        Tri t{rep[in[0]], rep[in[1]], rep[in[2]]};
        // A triangle that welding collapses onto an edge or point was only a sliver.
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
        for (auto& i : t) {
            if (new_index[i] == kUnused) {
                new_index[i] = static_cast<std::uint32_t>(stone.vertices.size());
                stone.vertices.push_back(positions[i]);
            }
            i = new_index[i];
        }
        tris.push_back(t);
        source.push_back(n);
    }
    const std::vector<glm::dvec3>& v = stone.vertices;
    for (std::size_t t = 0; t < tris.size(); ++t) {
        if (glm::length(area_vector(v, tris[t])) <= 1e-14 * size * size) {
            return Error{"triangle " + std::to_string(source[t]) +
                         " has no area (its corners are in a line)"};
        }
    }

    // Closed and 2-manifold with consistent winding: every directed edge exactly once, and its
    // reverse exactly once.
    std::unordered_map<std::uint64_t, std::uint32_t> owner;
    std::size_t repeated = 0;
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!owner.emplace(edge_key(tris[t][k], tris[t][(k + 1) % 3]), t).second) ++repeated;
        }
    }
    if (repeated > 0) {
        return Error{"mesh is not 2-manifold or not consistently wound: " +
                     std::to_string(repeated) + " edges used twice in the same direction"};
    }
    std::size_t boundary = 0;
    for (const auto& [key, t] : owner) {
        if (!owner.contains(edge_key(static_cast<std::uint32_t>(key), key >> 32))) ++boundary;
    }
    if (boundary > 0) {
        return Error{"mesh is open: " + std::to_string(boundary) + " boundary edges"};
    }

    // A mesh wound inward as a whole is still a valid solid: turn it outward.
    double volume6 = 0.0;
    for (const auto& t : tris) volume6 += glm::dot(v[t[0]], glm::cross(v[t[1]], v[t[2]]));
    if (std::abs(volume6) <= 1e-12 * size * size * size) return Error{"mesh encloses no volume"};
    if (volume6 < 0.0) {
        std::unordered_map<std::uint64_t, std::uint32_t> flipped;
        for (auto& t : tris) std::swap(t[1], t[2]);
        for (const auto& [key, t] : owner) {
            flipped.emplace(edge_key(static_cast<std::uint32_t>(key), key >> 32), t);
        }
        owner = std::move(flipped);
    }

    // Merge neighbours whose planes agree: the far vertex of each lies on the other's plane.
    const double planar_tol = planar_tolerance * size;
    // Neighbours folded flat onto each other (a non-convex polygon fanned from one corner)
    // would enclose nothing between them: not a solid's surface.
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
        const glm::dvec3 n = glm::normalize(area_vector(v, tris[t]));
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = owner.at(edge_key(tris[t][(k + 1) % 3], tris[t][k]));
            if (glm::dot(n, glm::normalize(area_vector(v, tris[u]))) < -1.0 + 1e-12) {
                return Error{"triangles " + std::to_string(t) + " and " + std::to_string(u) +
                             " fold over each other"};
            }
        }
    }
    // Facets grown from the largest triangles: a neighbour joins when its corners lie on the
    // plane of the facet grown so far (its area-weighted normal, which rounding of inner
    // corners cannot tilt: the sum of a planar polygon's triangles' area vectors is its own).
    // A single triangle's normal tilts with any rounding of its corners, most of all a
    // sliver's; a grown facet's barely does, so the tolerance can follow the rounding itself.
    std::vector<std::uint32_t> order(tris.size());
    std::iota(order.begin(), order.end(), 0u);
    std::vector<double> area2(tris.size());
    for (std::uint32_t t = 0; t < tris.size(); ++t) area2[t] = glm::length(area_vector(v, tris[t]));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return area2[a] > area2[b]; });
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> group_of(tris.size(), kNone);
    std::vector<std::vector<std::uint32_t>> members;
    for (std::uint32_t seed : order) {
        if (group_of[seed] != kNone) continue;
        const auto g = static_cast<std::uint32_t>(members.size());
        members.push_back({seed});
        group_of[seed] = g;
        glm::dvec3 normal_sum(0.0), centroid_sum(0.0);
        double area_sum = 0.0;
        const auto take = [&](std::uint32_t t) {
            normal_sum += area_vector(v, tris[t]);
            centroid_sum += area2[t] * (v[tris[t][0]] + v[tris[t][1]] + v[tris[t][2]]) / 3.0;
            area_sum += area2[t];
        };
        take(seed);
        for (std::size_t next = 0; next < members[g].size(); ++next) {
            const std::uint32_t t = members[g][next];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t u = owner.at(edge_key(tris[t][(k + 1) % 3], tris[t][k]));
                if (group_of[u] != kNone) continue;
                const glm::dvec3 n = glm::normalize(normal_sum);
                const double d = glm::dot(n, centroid_sum / area_sum);
                if (glm::dot(n, area_vector(v, tris[u])) <= 0.0) continue;
                bool coplanar = true;
                for (std::uint32_t w : tris[u]) {
                    coplanar = coplanar && std::abs(glm::dot(n, v[w]) - d) <= planar_tol;
                }
                if (!coplanar) continue;
                group_of[u] = g;
                members[g].push_back(u);
                take(u);
            }
        }
    }
    // A group whose boundary is not one simple loop cannot be one Facet; its triangles then
    // stay separate facets, which still describe the same surface.
    for (const auto& group : members) {
        std::vector<std::uint32_t> loop = boundary_loop(group, tris, group_of, owner);
        std::vector<std::vector<std::uint32_t>> parts;
        if (loop.empty()) {
            for (std::uint32_t t : group) parts.push_back({t});
        } else {
            parts.push_back(group);
        }
        for (const auto& part : parts) {
            Facet facet;
            facet.plane = fit_plane(v, tris, part);
            facet.loop =
                part.size() == 1 && loop.empty()
                    ? std::vector<std::uint32_t>(tris[part[0]].begin(), tris[part[0]].end())
                    : loop;
            const auto facet_index = static_cast<std::uint32_t>(stone.facets.size());
            for (std::uint32_t t : part) stone.triangles.push_back({tris[t], facet_index});
            stone.facets.push_back(std::move(facet));
        }
    }

    stone.convex = std::all_of(stone.facets.begin(), stone.facets.end(), [&](const Facet& f) {
        return std::all_of(v.begin(), v.end(), [&](const glm::dvec3& p) {
            return f.plane.signed_distance(p) <= planar_tol;
        });
    });
    return stone;
}

Result<Stone> stone_closed_by_its_planes(const std::vector<glm::dvec3>& positions,
                                         const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                         std::string name, double planar_tolerance) {
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double size = glm::length(hi - lo);
    if (!(size > 0.0)) return Error{"mesh has no extent"};
    const double tol = planar_tolerance * size;
    // The triangles' planes, largest first, each joining the first plane it lies in: within
    // the tolerance at its own corners (which fixes both the normal and the offset).
    std::vector<std::uint32_t> order;
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        const auto& tri = triangles[t];
        if (tri[0] >= positions.size() || tri[1] >= positions.size() || tri[2] >= positions.size())
            return Error{"a triangle refers past the vertices"};
        order.push_back(t);
    }
    const auto area = [&](std::uint32_t t) {
        const auto& c = triangles[t];
        return glm::cross(positions[c[1]] - positions[c[0]], positions[c[2]] - positions[c[0]]);
    };
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return glm::length(area(a)) > glm::length(area(b));
    });
    struct Cluster {
        glm::dvec3 normal_sum{0.0}, centroid_sum{0.0};
        double weight = 0.0;
        Plane plane() const {
            Plane p;
            p.n = glm::normalize(normal_sum);
            p.d = glm::dot(p.n, centroid_sum / weight);
            return p;
        }
    };
    std::vector<Cluster> clusters;
    for (std::uint32_t t : order) {
        const glm::dvec3 a = area(t);
        const double w = glm::length(a);
        if (!(w > 0.0)) continue;
        const auto& c = triangles[t];
        Cluster* home = nullptr;
        for (Cluster& k : clusters) {
            const Plane p = k.plane();
            if (glm::dot(p.n, a) <= 0.0) continue;
            bool in = true;
            for (std::uint32_t v : c) in = in && std::abs(p.signed_distance(positions[v])) <= tol;
            if (in) {
                home = &k;
                break;
            }
        }
        if (home == nullptr) home = &clusters.emplace_back();
        home->normal_sum += a;
        home->centroid_sum += w * (positions[c[0]] + positions[c[1]] + positions[c[2]]) / 3.0;
        home->weight += w;
    }
    // Nearly convex: every corner inside every plane, within the tolerance.
    std::vector<FacetPlane> planes;
    for (const Cluster& k : clusters) {
        const Plane p = k.plane();
        for (const glm::dvec3& v : positions) {
            if (p.signed_distance(v) > tol) {
                return Error{"not convex, so its missing faces cannot be told from its planes"};
            }
        }
        planes.push_back({p, FacetKind::other, ""});
    }
    auto closed = stone_from_planes(planes, std::move(name));
    if (!closed) return Error{closed.error()};
    // A whole facet lost leaves no plane for it: the planes then close the stone somewhere it
    // never reached (a point above a missing table). Every corner must be one the mesh had,
    // within what intersecting fitted planes at shallow angles may move it.
    const double moved = std::max(10.0 * tol, 1e-3 * size);
    for (const glm::dvec3& corner : closed.value().vertices) {
        double nearest = HUGE_VAL;
        for (const glm::dvec3& p : positions) nearest = std::min(nearest, glm::length(corner - p));
        if (nearest > moved) {
            return Error{"a whole facet is missing, so its planes would change its shape"};
        }
    }
    return closed;
}

}  // namespace gem
