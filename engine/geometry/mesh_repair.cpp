#include "geometry/mesh_repair.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include "geometry/triangulate.hpp"

namespace gem {

namespace {

std::uint64_t directed(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(a) << 32) | b;
}
std::uint64_t undirected(std::uint32_t a, std::uint32_t b) {
    return directed(std::min(a, b), std::max(a, b));
}

double extent(const std::vector<glm::dvec3>& positions, const MeshTriangles& triangles) {
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const auto& t : triangles) {
        for (std::uint32_t i : t) {
            lo = glm::min(lo, positions[i]);
            hi = glm::max(hi, positions[i]);
        }
    }
    return triangles.empty() ? 0.0 : glm::length(hi - lo);
}

}  // namespace

std::size_t drop_zero_area_triangles(const std::vector<glm::dvec3>& positions,
                                     MeshTriangles& triangles, double relative) {
    const double least = relative * extent(positions, triangles);
    const auto repeated = [](const std::array<std::uint32_t, 3>& tri) {
        return tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0];
    };
    const auto flat = [&](const std::array<std::uint32_t, 3>& tri) {
        const glm::dvec3 a = positions[tri[0]], b = positions[tri[1]], c = positions[tri[2]];
        const double longest_edge =
            std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
        return repeated(tri) || !(glm::length(glm::cross(b - a, c - a)) > least * longest_edge);
    };
    std::size_t dropped = 0;
    for (std::size_t t = 0; t < triangles.size();) {
        const auto tri = triangles[t];
        if (!flat(tri)) {
            ++t;
            continue;
        }
        triangles[t] = triangles.back();
        triangles.pop_back();
        ++dropped;
        if (repeated(tri)) continue;
        // The long edge p → q and the corner m on it; the neighbour holds q → p.
        int m = 0;
        double longest = -1.0;
        for (int k = 0; k < 3; ++k) {
            const double l = glm::length(positions[tri[(k + 1) % 3]] - positions[tri[(k + 2) % 3]]);
            if (l > longest) {
                longest = l;
                m = k;
            }
        }
        const std::uint32_t p = tri[(m + 1) % 3], q = tri[(m + 2) % 3], mid = tri[m];
        for (std::size_t n = 0; n < triangles.size(); ++n) {
            const auto other = triangles[n];
            int k = 0;
            while (k < 3 && !(other[k] == q && other[(k + 1) % 3] == p)) ++k;
            if (k == 3) continue;
            const std::uint32_t x = other[(k + 2) % 3];
            // Split only where both halves have area: a neighbour that is itself a sliver
            // would be split back and forth (a fuzzed file did), and is dropped in its turn.
            const std::array<std::uint32_t, 3> first{q, mid, x}, second{mid, p, x};
            if (flat(first) || flat(second)) break;
            triangles[n] = first;
            triangles.push_back(second);
            break;
        }
    }
    return dropped;
}

Result<std::size_t> orient_consistently(MeshTriangles& triangles) {
    // Each undirected edge's triangles (at most two on a surface).
    std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> sides;
    constexpr std::uint32_t kNone = ~0u;
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const auto key = undirected(triangles[t][k], triangles[t][(k + 1) % 3]);
            auto [it, fresh] = sides.try_emplace(key, std::array<std::uint32_t, 2>{t, kNone});
            if (fresh) continue;
            if (it->second[1] != kNone) {
                return Error{"an edge is shared by more than two triangles (not a surface)"};
            }
            it->second[1] = t;
        }
    }
    const auto has_directed = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
        for (int k = 0; k < 3; ++k) {
            if (triangles[t][k] == a && triangles[t][(k + 1) % 3] == b) return true;
        }
        return false;
    };
    std::vector<char> seen(triangles.size(), 0);
    std::vector<std::uint32_t> stack;
    std::size_t turned = 0;
    for (std::uint32_t start = 0; start < triangles.size(); ++start) {
        if (seen[start]) continue;
        seen[start] = 1;
        stack.push_back(start);
        while (!stack.empty()) {
            const std::uint32_t t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                const auto& pair = sides.at(undirected(a, b));
                const std::uint32_t n = pair[0] == t ? pair[1] : pair[0];
                if (n == kNone || n == t) continue;
                // A neighbour wound as this one runs the shared edge the other way.
                const bool agrees = !has_directed(n, a, b);
                if (seen[n]) {
                    if (!agrees) return Error{"its triangles cannot all be wound one way"};
                    continue;
                }
                if (!agrees) {
                    std::swap(triangles[n][1], triangles[n][2]);
                    ++turned;
                }
                seen[n] = 1;
                stack.push_back(n);
            }
        }
    }
    return turned;
}

Result<std::size_t> fill_holes(const std::vector<glm::dvec3>& positions, MeshTriangles& triangles) {
    std::unordered_map<std::uint64_t, int> count;
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) ++count[directed(t[k], t[(k + 1) % 3])];
    }
    // A boundary edge a → b is crossed by the filling as b → a: the loop's next corner after b
    // is a.
    std::unordered_map<std::uint32_t, std::uint32_t> next;
    for (const auto& [key, n] : count) {
        const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
        if (count.contains(directed(b, a))) continue;
        if (!next.emplace(b, a).second) {
            return Error{"its open edges meet at a corner more than twice (not simple holes)"};
        }
    }
    std::size_t holes = 0;
    while (!next.empty()) {
        std::vector<std::uint32_t> loop;
        std::uint32_t v = next.begin()->first;
        while (true) {
            const auto it = next.find(v);
            if (it == next.end()) break;
            loop.push_back(v);
            v = it->second;
            next.erase(it);
        }
        if (loop.size() < 3 || v != loop.front()) {
            return Error{"its open edges do not close into loops"};
        }
        // The side from which the loop winds counter-clockwise is the outward side of the
        // triangles that fill it.
        const glm::dvec3 normal = newell_normal(positions, loop);
        if (!(glm::length(normal) > 0.0)) return Error{"a hole with no area"};
        // A loop that is not simple in its plane gives triangles that overlap: the stone
        // built from them then fails its own checks, naming what is wrong.
        triangulate_polygon(positions, loop, glm::normalize(normal), triangles);
        ++holes;
    }
    return holes;
}

}  // namespace gem
