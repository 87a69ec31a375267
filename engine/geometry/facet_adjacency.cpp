#include "geometry/facet_adjacency.hpp"

#include <algorithm>
#include <map>

namespace gem {

FacetAdjacency facet_adjacency(const Stone& stone) {
    const auto facets = static_cast<std::uint32_t>(stone.facets.size());
    // Facets at every corner.
    std::vector<std::vector<std::uint32_t>> at_vertex(stone.vertices.size());
    for (std::uint32_t f = 0; f < facets; ++f) {
        for (std::uint32_t v : stone.facets[f].loop) {
            auto& list = at_vertex[v];
            if (list.empty() || list.back() != f) list.push_back(f);
        }
    }
    FacetAdjacency out;
    out.first.resize(facets);
    out.edge_count.resize(facets);
    out.vertex_count.resize(facets);
    for (std::uint32_t f = 0; f < facets; ++f) {
        std::map<std::uint32_t, int> shared;  // neighbour → corners in common
        for (std::uint32_t v : stone.facets[f].loop) {
            for (std::uint32_t g : at_vertex[v]) {
                if (g != f) ++shared[g];
            }
        }
        // Edge neighbours in loop order: the facet across edge (a, b) shares both corners.
        std::vector<std::uint32_t> edges;
        const auto& loop = stone.facets[f].loop;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::uint32_t a = loop[i];
            const std::uint32_t b = loop[(i + 1) % loop.size()];
            for (std::uint32_t g : at_vertex[a]) {
                if (g == f || shared[g] < 2) continue;
                const auto& other = at_vertex[b];
                if (std::find(other.begin(), other.end(), g) == other.end()) continue;
                if (std::find(edges.begin(), edges.end(), g) == edges.end()) edges.push_back(g);
            }
        }
        // Facets sharing two corners that are not the ends of one edge (a T-junction).
        for (const auto& [g, count] : shared) {
            if (count >= 2 && std::find(edges.begin(), edges.end(), g) == edges.end()) {
                edges.push_back(g);
            }
        }
        out.first[f] = static_cast<std::uint32_t>(out.list.size());
        out.edge_count[f] = static_cast<std::uint32_t>(edges.size());
        out.list.insert(out.list.end(), edges.begin(), edges.end());
        std::uint32_t corners_only = 0;
        for (const auto& [g, count] : shared) {
            if (count == 1) {
                out.list.push_back(g);
                ++corners_only;
            }
        }
        out.vertex_count[f] = corners_only;
    }
    return out;
}

}  // namespace gem
