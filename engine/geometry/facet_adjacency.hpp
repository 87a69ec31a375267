#pragma once
// Which facets touch which (docs/design.md, "Exact exits"): per facet its edge neighbours
// (the facets across its loop's edges, one per edge) and the facets that share only a vertex
// with it. A convex facet is the intersection of its plane with its edge neighbours'
// half-spaces, so testing a point against those planes says whether it lies on the facet; the
// vertex neighbours settle ties where an exit lands on a corner.

#include <cstdint>
#include <vector>

#include "geometry/stone.hpp"

namespace gem {

struct FacetAdjacency {
    // Per facet f: its neighbours are list[first[f] .. first[f] + edge_count[f] + vertex_count[f]),
    // the edge neighbours first (in loop order), then the vertex-only ones (ascending).
    std::vector<std::uint32_t> first;
    std::vector<std::uint32_t> edge_count;
    std::vector<std::uint32_t> vertex_count;
    std::vector<std::uint32_t> list;

    std::size_t facets() const { return first.size(); }
    const std::uint32_t* edges_of(std::uint32_t f) const { return list.data() + first[f]; }
    const std::uint32_t* vertices_of(std::uint32_t f) const {
        return list.data() + first[f] + edge_count[f];
    }
};

// From the facets' vertex loops, which share vertex indices (the half-space intersection and
// the mesh importers weld corners). Two facets sharing two or more corners count as edge
// neighbours, so a corner left in the middle of a neighbour's edge (a T-junction) still makes
// them neighbours; one corner makes them vertex neighbours. Only the walk's speed depends on
// the split: any plane it tests that the point lies outside of leads it closer to the exit.
FacetAdjacency facet_adjacency(const Stone& stone);

}  // namespace gem
