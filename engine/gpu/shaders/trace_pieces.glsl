// The trace method's exits from a non-convex stone (trace.frag, NON_CONVEX): through its
// convex pieces (PIECES), else through its triangles, brute force.
#ifdef NON_CONVEX
// Hits down to this far behind the origin count (mm), so a ray starting on an edge that
// leaves straight through the neighbouring facet is caught there (bvh_intersector.cpp uses
// 1e-9 of the diagonal in double; float needs more).
const float kBehind = 1e-5;

#ifdef PIECES
// The stone as convex pieces (trace/convex_pieces.hpp; pieces_intersector.cpp is the CPU twin),
// their planes as constants: trace_method.cpp writes PIECE_COUNT, PIECE_LOCATE (the partition
// as nested selects of below_cut), PIECE_BOUNDS (below; id a plane's facet or -1 for a cut),
// PIECE_POCKET_WALL and POCKET_WALLS (below).
// A point this near a cut (mm) is on it: it goes where its direction points.
const float kOnCut = 1e-5;

bool below_cut(vec3 p, vec3 d, vec3 n, float w) {
    float s = dot(n, p) - w;
    return s < -kOnCut || (s <= kOnCut && dot(n, d) <= 0.0);
}

int entry_piece(vec3 p, vec3 d) {
    return PIECE_LOCATE;
}

// A ray leaving through a facet on the stone's convex hull leaves the hull there, and a convex
// solid is not met again: only the pockets' walls (PIECE_POCKET_WALL, a test of `facet`) may
// send a ray back in.
bool may_reenter(int facet) {
    return PIECE_POCKET_WALL;
}

// Every plane once (PIECE_BOUNDS: one PIECE_BOUND(id, mask, n.x, n.y, n.z, d) per plane, mask
// the pieces it bounds as bits), the nearest ahead kept for each piece at once: a ray that
// crosses a cut goes on to the piece beyond's nearest, found in the same pass.
#define PIECE_BOUND(id, mask, nx, ny, nz, dd)                                        \
    {                                                                                \
        float f = dot(vec3(nx, ny, nz), d);                                          \
        float t = max((dd - dot(vec3(nx, ny, nz), o)) / f, 0.0);                     \
        bool ahead = f > 0.0 && (id < 0 || id != from_facet);                        \
        bvec4 better = bvec4(ahead && (mask & 1) != 0 && t < t_piece.x,              \
                             ahead && (mask & 2) != 0 && t < t_piece.y,              \
                             ahead && (mask & 4) != 0 && t < t_piece.z,              \
                             ahead && (mask & 8) != 0 && t < t_piece.w);             \
        t_piece = mix(t_piece, vec4(t), better);                                     \
        bound = ivec4(better.x ? id : bound.x, better.y ? id : bound.y,              \
                      better.z ? id : bound.z, better.w ? id : bound.w);             \
    }

// The nearest plane ahead in `piece`; through a cut, on in the piece beyond (each crossing
// enters a piece further along, so there are fewer crossings than pieces).
bool next_exit(vec3 o, vec3 d, int from_facet, inout int piece, out float t_hit, out int facet) {
    vec4 t_piece = vec4(1e30);
    ivec4 bound = ivec4(-2);
    PIECE_BOUNDS
    for (int crossing = 0; crossing < PIECE_COUNT; ++crossing) {
        t_hit = t_piece[piece];
        int b = bound[piece];
        if (b == -2) return false;
        if (b >= 0) {
            facet = b;
            return true;
        }
        piece = entry_piece(o + t_hit * d, d);
    }
    return false;
}

// A ray that leaves through a pocket wall is inside the stone's convex hull, and can meet the
// stone again only on a pocket wall (the other facets bound the hull): POCKET_WALLS holds, per
// convex part of a wall, WALL_BEGIN(facet, n.x, n.y, n.z, d), a WALL_EDGE(n.x, n.y, n.z, d) per
// edge (facing out of the polygon) and WALL_END(facet).
const float kWallSlack = 1e-5;  // mm: a ray through the edge of two polygons meets one of them
#define WALL_BEGIN(id, nx, ny, nz, dd)                                    \
    {                                                                     \
        float f = dot(vec3(nx, ny, nz), d);                               \
        float t = (dd - dot(vec3(nx, ny, nz), o)) / f;                    \
        vec3 q = o + t * d;                                               \
        bool on = f < 0.0 && id != from_facet && t > -kBehind && t < t_hit;
#define WALL_EDGE(nx, ny, nz, dd) on = on && dot(vec3(nx, ny, nz), q) <= dd + kWallSlack;
#define WALL_END(id)              \
        t_hit = on ? t : t_hit;   \
        facet = on ? id : facet;  \
    }

// Where a ray leaving the stone through pocket wall `from_facet` comes back in, and into which
// piece.
bool next_entry_from(vec3 o, vec3 d, int from_facet, out float t_hit, out int facet,
                     out int piece) {
    t_hit = 1e30;
    facet = -1;
    POCKET_WALLS
    piece = entry_piece(o + t_hit * d, d);
    t_hit = max(t_hit, 0.0);
    return facet >= 0;
}

// shading.glsl's obstruction test: from any facet but a pocket wall a ray leaves the stone's
// convex hull, so nothing can hide the light.
bool stone_ahead(vec3 p, vec3 d, int facet, float limit) {
    float t;
    int entered;
    int piece;
    return may_reenter(facet) && next_entry_from(p, d, facet, t, entered, piece) && t < limit;
}

#else
// Barycentric slack: Moller-Trumbore in float can let a ray through the shared edge of two
// triangles slip between them; a hair of overlap closes the crack.
const float kEdgeSlack = 1e-5;

// Nearest triangle hit whose facet normal n has sign(n.d) == side (-1 entering, +1 leaving).
bool nearest_triangle(vec3 o, vec3 d, int from_facet, float side, out float t_hit,
                      out int facet) {
    t_hit = 1e30;
    facet = -1;
    for (int i = 0; i < u_triangle_count; ++i) {
        vec4 a = texelFetch(u_triangles, texel_of(3 * i), 0);
        int f = int(a.w + 0.5);
        if (f == from_facet) continue;
        vec3 b = texelFetch(u_triangles, texel_of(3 * i + 1), 0).xyz;
        vec3 c = texelFetch(u_triangles, texel_of(3 * i + 2), 0).xyz;
        vec3 e1 = b - a.xyz;
        vec3 e2 = c - a.xyz;
        // Counter-clockwise seen from outside: e1 x e2 points out, as the facet normal does.
        if (dot(cross(e1, e2), d) * side <= 0.0) continue;
        vec3 q = cross(d, e2);
        float det = dot(e1, q);
        if (det == 0.0) continue;
        float inv = 1.0 / det;
        vec3 s = o - a.xyz;
        float u = dot(s, q) * inv;
        if (u < -kEdgeSlack || u > 1.0 + kEdgeSlack) continue;
        vec3 r = cross(s, e1);
        float v = dot(d, r) * inv;
        if (v < -kEdgeSlack || u + v > 1.0 + kEdgeSlack) continue;
        float t = dot(e2, r) * inv;
        if (t > -kBehind && t < t_hit) {
            t_hit = t;
            facet = f;
        }
    }
    t_hit = max(t_hit, 0.0);
    return facet >= 0;
}

// The triangles hold no pieces (`piece` is unused), nor know the pocket walls.
int entry_piece(vec3 p, vec3 d) {
    return 0;
}

bool may_reenter(int facet) {
    return true;
}

bool next_entry_from(vec3 o, vec3 d, int from_facet, out float t_hit, out int facet,
                     out int piece) {
    piece = 0;
    return nearest_triangle(o, d, from_facet, -1.0, t_hit, facet);
}

// As bvh_intersector.cpp's next_exit; its fallback for a start point on an edge (leave where
// it stands through the steepest neighbour) is approximated by the planes through the point.
bool next_exit(vec3 o, vec3 d, int from_facet, inout int piece, out float t_hit, out int facet) {
    if (nearest_triangle(o, d, from_facet, 1.0, t_hit, facet)) return true;
    float steepest = 0.0;
    for (int i = 0; i < u_facet_count; ++i) {
        if (i == from_facet) continue;
        vec4 plane = facet_plane(i);
        float leaving = dot(plane.xyz, d);
        if (leaving <= steepest || abs(dot(plane.xyz, o) - plane.w) > kBehind) continue;
        steepest = leaving;
        facet = i;
    }
    t_hit = 0.0;
    return facet >= 0;
}

#endif  // PIECES
#endif  // NON_CONVEX
