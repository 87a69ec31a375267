// The stone's facets for every stone shader (stone_geometry.hpp): planes (n.xyz, d: n.p = d
// on the facet, n out of the stone) and each facet's edge neighbours, in one uniform block:
// constants every fragment reads, no texture fetches.
const int kMaxFacets = 256;      // stone_geometry.hpp: kMaxFacets
const int kMaxNeighbours = 3072; // stone_geometry.hpp: kMaxNeighbours

layout(std140) uniform StoneFacets {
    vec4 u_facet_plane[kMaxFacets];
    uvec4 u_facet_links[kMaxFacets / 4];              // first slot | edge count << 16
    uvec4 u_facet_neighbours[kMaxNeighbours / 8];     // 16-bit facet indices
};

vec4 facet_plane(int facet) { return u_facet_plane[facet]; }

// The slots of facet's edge neighbours: first, count.
ivec2 facet_neighbour_slots(int facet) {
    uint links = u_facet_links[facet >> 2][facet & 3];
    return ivec2(int(links & 0xFFFFu), int(links >> 16));
}

int facet_neighbour(int slot) {
    uint pair = u_facet_neighbours[slot >> 3][(slot >> 1) & 3];
    return int((pair >> (16u * uint(slot & 1))) & 0xFFFFu);
}
