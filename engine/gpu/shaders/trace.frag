// The trace method: the exact tracer (engine/trace/tracer.cpp) per fragment of the stone pass,
// shaded with shading.glsl. The rasteriser gives the entry facet and point; the entry splits
// the pixel ray into the first reflection and the ray inside; every facet hit inside splits a
// branch into an internal reflection (followed) and a refracted exit ray (shaded at once: a
// shaded ray needs no storage). Depth counts segments, branches below u_min_weight are cut,
// TIR keeps everything: the same rules as the CPU.
// Convex stones: one branch at a time, and each exit found by walking the facets from a first
// guess (trace/facet_walk.hpp, the CPU twin), with EXIT_UNROLLED by testing every plane,
// written into the shader as constants, or with EXIT_FOLDED by folding the ray into one wedge
// of a mirror-symmetric stone and testing the few planes there, also constants
// (trace/folded_exit.hpp, the CPU twin). trace_method.cpp measures which is fastest.
// NON_CONVEX: the stone's convex pieces with PIECES (trace/convex_pieces.hpp), else its
// triangles, brute force (a heart has a few hundred); exit rays are followed outside at once,
// and branches refracted back in through the cleft wait on a small fixed list; it traces fire
// only exactly (trace_method.cpp asks for it only in a still view's frames).
in vec3 v_position;  // the entry point, interpolated
flat in uint v_facet;
layout(location = 0) out vec4 o_colour;
#ifdef VISIBILITY
// Drawn as the rectangle about the stone, under a stencil test that keeps its own pixels (or
// samples): each pixel's entry facet from the visibility pass (stone_visibility.frag).
#ifdef VISIBILITY_SAMPLES
// Each sample's facet and stone (GLSL ES 3.10): the pixel's colour is written to the samples
// the stencil keeps, so each facet the stone shows there is traced once and weighed by its
// samples. The resolve averages a pixel's samples, so the picture is the one drawn facet by
// facet, each facet's triangle writing its own samples.
uniform highp usampler2DMS u_visibility;
uniform int u_samples;
uniform uint u_stone;
const int kMaxSamples = 8;  // VisibilityTarget::kMaxSamples
#else
uniform mediump usampler2D u_visibility;
#endif
#endif

uniform int u_facet_count;
uniform float u_ior;
uniform int u_max_depth;
uniform float u_min_weight;
uniform int u_thesis_weights;  // 1: constant R/T factors; 0: exact Fresnel
uniform float u_r_factor;
uniform float u_t_factor;
// n at each channel's wavelength: its dominant one, or a still frame's own
// (optics/spectrum.hpp, StillSpectrum)
uniform vec3 u_ior_channel;
// FIRE_EXACT: column k is what the trace at u_ior_channel[k] adds to each channel (the identity
// but for a still frame's wavelengths, whose traces also give the other channels' negative
// lobes: optics/spectrum.hpp, StillSpectrum)
uniform mat3 u_channel_mix;
const float kAir = 1.0;
// Fire (compiled in, program_variants.hpp): none by default; FIRE_FIRST_ORDER moves exit
// directions by d(direction)/dn (n(channel) - n) as the table method does; FIRE_EXACT traces
// every channel at its own index.
#ifdef FIRE_FIRST_ORDER
const bool kFirstOrder = true;
#else
const bool kFirstOrder = false;
#endif

// Weight shares of an interaction from index n1 into n2 at incidence cosine cos_i and
// transmission cosine cos_t (optics/fresnel.cpp; tracer.cpp split_weight). x: reflected,
// y: transmitted. `total`: total internal reflection, which reflects everything.
vec2 fresnel_split(float cos_i, float cos_t, float n1, float n2, bool total) {
    float s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    // Selects, not early returns: under TIR the quotients may be 0/0.
    float r = total ? 1.0 : min(0.5 * (s * s + p * p), 1.0);
    bool factors = u_thesis_weights == 1 && r < 1.0;
    return factors ? vec2(u_r_factor, u_t_factor) : vec2(r, 1.0 - r);
}

vec2 split_weight(float cos_i, float n1, float n2) {
    cos_i = clamp(cos_i, 0.0, 1.0);
    float sin_t2 = (n1 / n2) * (n1 / n2) * (1.0 - cos_i * cos_i);
    return fresnel_split(cos_i, sqrt(max(1.0 - sin_t2, 0.0)), n1, n2, sin_t2 >= 1.0);
}

// A ray along d meeting the stone's surface from inside, at a facet with outward normal n:
// the weight shares as split_weight gives them and the direction it leaves along (Snell;
// unused under TIR, where the transmitted share is 0). Fresnel and Snell share cos_t, and
// the direction needs no normalising: from unit d and n it is a unit vector.
vec2 leave_stone(vec3 d, vec3 n, float ior, out vec3 out_dir) {
    float cos_i = clamp(dot(d, n), 0.0, 1.0);
    float sin_t2 = ior * ior * (1.0 - cos_i * cos_i);
    float cos_t = sqrt(max(1.0 - sin_t2, 0.0));
    out_dir = ior * d + (cos_t - ior * cos_i) * n;
    return fresnel_split(cos_i, cos_t, ior, kAir, sin_t2 >= 1.0);
}

// Snell refraction of d through the surface with normal n facing against d; false on TIR.
bool refract_ray(vec3 d, vec3 n, float n1, float n2, out vec3 refracted) {
    float eta = n1 / n2;
    float cos_i = -dot(d, n);
    float sin2_t = eta * eta * max(0.0, 1.0 - cos_i * cos_i);
    refracted = vec3(0.0);
    if (sin2_t >= 1.0) return false;
    refracted = normalize(eta * d + (eta * cos_i - sqrt(1.0 - sin2_t)) * n);
    return true;
}

#ifndef NON_CONVEX

// The first guess of the exit facet: where a ray from the centre along d leaves.
uniform highp usamplerCube u_exit_guess;

// Steps a walk may take (the CPU twin's longest on any cut is well below): a bound on the
// work, never reached on a valid stone.
const int kMaxWalkSteps = 32;

#ifdef EXIT_UNROLLED
// Every plane as constants, unrolled (STONE_EXIT_PLANES: trace_method.cpp writes one
// EXIT_PLANE(index, n.x, n.y, n.z, d) per facet): no memory reads and no divergent loop, which a
// SIMD rasteriser (llvmpipe) runs faster than the walk's few scattered reads.
#define EXIT_PLANE(i, nx, ny, nz, w)                              \
    {                                                              \
        float f = dot(vec3(nx, ny, nz), d);                        \
        float t = max((w - dot(vec3(nx, ny, nz), o)) / f, 0.0);    \
        bool better = f > 0.0 && i != from_facet && t < t_hit;     \
        t_hit = better ? t : t_hit;                                \
        facet = better ? i : facet;                                \
    }
int exit_by_constants(vec3 o, vec3 d, int from_facet, out float t_hit) {
    t_hit = 1e30;
    int facet = -1;
    STONE_EXIT_PLANES
    return facet;
}
#endif

#ifdef EXIT_FOLDED
// trace/folded_exit.hpp: FOLD_LEVELS mirrors after x = 0 and z = 0 (FOLD_MIRROR_LIST, unit
// normals in x, z), the first wedge's edges (FOLD_EDGE_LO, FOLD_EDGE_HI) and how far inside
// them a point is taken (FOLD_INSIDE, mm), the first guess's solid (FOLD_GUESS_Z_SCALE,
// FOLD_GUESS_RADIUS, FOLD_GUESS_Y: y_min, y_max; FOLD_GUESS_PAVILION and FOLD_GUESS_CROWN:
// slope, apex y, where the cone is there), and FOLDED_PLANES: one
// FOLDED_PLANE(n.x, n.y, n.z, d) per facet reaching inside the first wedge.
#if FOLD_LEVELS > 0
const vec2 kFoldMirror[FOLD_LEVELS] = vec2[](FOLD_MIRROR_LIST);
#endif
const float kFacingMin = 1e-6;  // folded_exit.hpp: kFacingMin

vec2 reflect_across(vec2 p, vec2 m, bool across) {
    return across ? p - 2.0 * dot(p, m) * m : p;
}

// Folds the ray (o, d) by the fold that takes point p into the first wedge, and returns that
// fold as bits (folded_exit.cpp: fold_bits): the ray is folded as p is, a mirror at a time.
uint fold_ray(vec2 p, inout vec3 o, inout vec3 d) {
    bvec2 negative = lessThan(p, vec2(0.0));
    uint bits = (negative.x ? 1u : 0u) | (negative.y ? 2u : 0u);
    vec2 flip = vec2(negative.x ? -1.0 : 1.0, negative.y ? -1.0 : 1.0);
    p = abs(p);
    o.xz *= flip;
    d.xz *= flip;
#if FOLD_LEVELS > 0
    for (int i = 0; i < FOLD_LEVELS; ++i) {
        bool beyond = dot(p, kFoldMirror[i]) > 0.0;
        p = reflect_across(p, kFoldMirror[i], beyond);
        o.xz = reflect_across(o.xz, kFoldMirror[i], beyond);
        d.xz = reflect_across(d.xz, kFoldMirror[i], beyond);
        bits |= beyond ? (4u << uint(i)) : 0u;
    }
#endif
    return bits;
}

vec3 unfold_vector(vec3 v, uint bits) {
    vec2 p = v.xz;
#if FOLD_LEVELS > 0
    for (int i = FOLD_LEVELS - 1; i >= 0; --i) {
        p = reflect_across(p, kFoldMirror[i], (bits & (4u << uint(i))) != 0u);
    }
#endif
    return vec3((bits & 1u) != 0u ? -p.x : p.x, v.y, (bits & 2u) != 0u ? -p.y : p.y);
}

#define FOLDED_PLANE(nx, ny, nz, w)                                     \
    {                                                                   \
        float f = dot(vec3(nx, ny, nz), df);                            \
        float t = max(w - dot(vec3(nx, ny, nz), of), 0.0) / f;          \
        bool better = f > kFacingMin && t < t_round;                    \
        t_round = better ? t : t_round;                                 \
        n_round = better ? vec3(nx, ny, nz) : n_round;                  \
    }

// folded_exit.cpp, leave_cone: one root of the ray against the cone r = k side (y - apex_y),
// taken when it is ahead, before `best`, on the cone's own nappe and crossing it outward.
float cone_root(vec3 o, vec3 d, float k2, float apex_y, float side, float t, float best) {
    vec3 p = o + t * d;
    float outward = p.x * d.x + p.z * d.z - k2 * (p.y - apex_y) * d.y;
    return t > 0.0 && t < best && side * (p.y - apex_y) >= 0.0 && outward > 0.0 ? t : best;
}

float leave_cone(vec3 o, vec3 d, float k, float apex_y, float side) {
    float k2 = k * k;
    float a = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    float b = o.x * d.x + o.z * d.z - k2 * (o.y - apex_y) * d.y;
    float c = o.x * o.x + o.z * o.z - k2 * (o.y - apex_y) * (o.y - apex_y);
    float root = sqrt(max(b * b - a * c, 0.0));
    float best = cone_root(o, d, k2, apex_y, side, (-b - root) / a, 1e30);
    return cone_root(o, d, k2, apex_y, side, (-b + root) / a, best);
}

// Where the ray leaves the stone turned about its axis (folded_exit.hpp: TurnedOutline); only
// its azimuth is used.
vec2 first_guess(vec3 o, vec3 d) {
    vec3 so = vec3(o.xy, o.z * FOLD_GUESS_Z_SCALE);
    vec3 sd = vec3(d.xy, d.z * FOLD_GUESS_Z_SCALE);
    float t = 1e30;
#ifdef FOLD_GUESS_PAVILION
    t = min(t, leave_cone(so, sd, FOLD_GUESS_PAVILION.x, FOLD_GUESS_PAVILION.y, 1.0));
#endif
#ifdef FOLD_GUESS_CROWN
    t = min(t, leave_cone(so, sd, FOLD_GUESS_CROWN.x, FOLD_GUESS_CROWN.y, -1.0));
#endif
    float a = dot(sd.xz, sd.xz);
    float b = dot(so.xz, sd.xz);
    float c = dot(so.xz, so.xz) - FOLD_GUESS_RADIUS * FOLD_GUESS_RADIUS;
    t = min(t, a > 0.0 ? (-b + sqrt(max(b * b - a * c, 0.0))) / a : 1e30);
    t = min(t, sd.y != 0.0 ? ((sd.y > 0.0 ? FOLD_GUESS_Y.y : FOLD_GUESS_Y.x) - so.y) / sd.y : 1e30);
    return (o + t * d).xz;
}

// The exit of the ray from o along d inside the stone: t, and the exit facet's normal.
float exit_by_folding(vec3 o, vec3 d, out vec3 n_exit) {
    vec2 target = first_guess(o, d);
    uint visited = 0u;
    float t_hit = 1e30;
    vec3 n_best = vec3(0.0);  // in the wedge of bits_best
    uint bits_best = 0u;
    for (int seen = 0; seen < FOLD_WEDGES; ++seen) {  // a round per wedge at most
        vec3 of = o;
        vec3 df = d;
        uint bits = fold_ray(target, of, df);
        if (((visited >> bits) & 1u) != 0u) break;  // its wedge was seen: the point is the exit
        visited |= 1u << bits;
        float t_round = t_hit;
        vec3 n_round = vec3(0.0);
        FOLDED_PLANES
        bool improved = t_round < t_hit;
        n_best = improved ? n_round : n_best;
        bits_best = improved ? bits : bits_best;
        t_hit = t_round;
        if (t_hit >= 1e30) {
            target = d.xz;  // nothing ahead here: the wedge d points into
            continue;
        }
        vec3 p = of + t_hit * df;
        float lo = dot(FOLD_EDGE_LO, p.xz);
        float hi = dot(FOLD_EDGE_HI, p.xz);
        if (lo >= FOLD_INSIDE && hi >= FOLD_INSIDE) break;
        // Next, the wedge the point lies in; one just inside an edge is pushed across it, so
        // the wedge beyond is tested too.
        p.xz -= (lo >= 0.0 && lo < FOLD_INSIDE ? 2.0 * FOLD_INSIDE : 0.0) * FOLD_EDGE_LO;
        p.xz -= (hi >= 0.0 && hi < FOLD_INSIDE ? 2.0 * FOLD_INSIDE : 0.0) * FOLD_EDGE_HI;
        target = unfold_vector(p, bits).xz;
    }
    n_exit = unfold_vector(n_best, bits_best);
    return t_hit;
}
#endif

// Every forward-facing plane, as convex_intersector.cpp does; for a guess that faces away.
int exit_by_search(vec3 o, vec3 d, int from_facet, out float t_hit) {
    t_hit = 1e30;
    int facet = -1;
    for (int i = 0; i < u_facet_count; ++i) {
        if (i == from_facet) continue;
        vec4 plane = facet_plane(i);
        float facing = dot(plane.xyz, d);
        if (facing <= 0.0) continue;
        float t = max((plane.w - dot(plane.xyz, o)) / facing, 0.0);
        if (t < t_hit) {
            t_hit = t;
            facet = i;
        }
    }
    return facet;
}

// The exit facet of the ray from o along d inside the stone (facet_walk.hpp): from the guess,
// move to the neighbour first crossed while the point on the candidate's plane lies outside
// a neighbour. t falls at every step, in float too (a step must lower it), so it ends.
int exit_by_walk(vec3 o, vec3 d, int from_facet, out float t_hit) {
    int g = int(texture(u_exit_guess, d).r);
    vec4 plane = facet_plane(g);
    float facing = dot(plane.xyz, d);
    if (g == from_facet || facing <= 0.0) return exit_by_search(o, d, from_facet, t_hit);
    float t = max((plane.w - dot(plane.xyz, o)) / facing, 0.0);
    for (int step = 0; step < kMaxWalkSteps; ++step) {
        vec3 p = o + t * d;
        ivec2 slots = facet_neighbour_slots(g);
        int next = -1;
        float t_next = t;
        for (int i = 0; i < slots.y; ++i) {
            int h = facet_neighbour(slots.x + i);
            vec4 ph = facet_plane(h);
            float f = dot(ph.xyz, d);
            if (f <= 0.0 || h == from_facet) continue;
            // On or inside h's plane (a point within rounding of an edge may go either way:
            // the step below must lower t, so neither choice can loop).
            if (dot(ph.xyz, p) - ph.w <= 0.0) continue;
            float th = max((ph.w - dot(ph.xyz, o)) / f, 0.0);
            if (th < t_next) {
                next = h;
                t_next = th;
            }
        }
        if (next < 0) break;
        g = next;
        t = t_next;
    }
    t_hit = t;
    return g;
}

// d(refracted)/d(eta) of Snell refraction of d through normal n (facing against d) at
// eta = n1/n2, with d fixed, plus its change with d along dd: a fixed facet chain's exit
// direction depends on the normals and the index only, so this chain rule is its exact
// derivative.
vec3 refraction_derivative(vec3 d, vec3 dd, vec3 n, float eta, float d_eta) {
    float c = -dot(d, n);
    float root = sqrt(max(1.0 - eta * eta * (1.0 - c * c), 1e-12));
    float dc = -dot(dd, n);
    vec3 by_eta = (d + (c + eta * (1.0 - c * c) / root) * n) * d_eta;
    vec3 by_d = eta * dd + (eta - eta * eta * c / root) * dc * n;
    return by_eta + by_d;
}

// Everything that leaves a convex stone from the ray refracted in at `entry` through `facet`
// with weight `weight`, traced at index `ior`. With first-order fire, each exit's colour
// channels are looked up along the direction moved by d(direction)/dn times
// (u_ior_channel - ior); dd is d(d)/dn.
vec3 follow_inside(vec3 entry, vec3 d, vec3 dd, int facet, float weight, float ior) {
    vec3 colour = vec3(0.0);
    vec3 o = entry;
    float path = 0.0;
    int from = facet;
    vec3 dn_channel = u_ior_channel - vec3(ior);
    for (int depth = 1; depth <= u_max_depth; ++depth) {
        if (weight <= 0.0 || weight < u_min_weight) break;
        float t;
        vec3 n;
#ifdef EXIT_FOLDED
        t = exit_by_folding(o, d, n);  // needs no starting facet (folded_exit.hpp)
        if (t >= 1e30) break;          // a closed solid always has an exit
#else
#ifdef EXIT_UNROLLED
        int exit_facet = exit_by_constants(o, d, from, t);
#else
        int exit_facet = exit_by_walk(o, d, from, t);
#endif
        if (exit_facet < 0) break;  // a closed solid always has one
        n = facet_plane(exit_facet).xyz;
        from = exit_facet;
#endif
        vec3 p = o + t * d;
        path += t;
        vec3 out_dir;
        vec2 split = leave_stone(d, n, ior, out_dir);
        float out_weight = weight * split.y;
        if (split.y > 0.0 && out_weight >= u_min_weight) {
            vec3 env;
            if (kFirstOrder) {
                vec3 dd_out = refraction_derivative(d, dd, -n, ior, 1.0);
                env = vec3(environment(p, normalize(out_dir + dd_out * dn_channel.r)).r,
                           environment(p, normalize(out_dir + dd_out * dn_channel.g)).g,
                           environment(p, normalize(out_dir + dd_out * dn_channel.b)).b);
            } else {
                env = environment(p, out_dir);
            }
            // A convex stone's lights are hidden only by the exit facet: no index needed.
            colour += shade_exit(p, out_dir, n, -1, out_weight, path, env);
        }
        o = p;
        d = reflect(d, n);
        if (kFirstOrder) dd -= 2.0 * dot(dd, n) * n;  // the derivative only where it is used
        weight *= split.x;
    }
    return colour;
}

#else

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

#endif

// An inside branch of the ray tree waiting its turn (tracer.cpp's Branch).
struct Inside {
    vec3 origin;
    vec3 direction;
    float weight;
    float path_mm;
    int facet;  // facet the branch starts on
    int depth;  // segments followed so far, this one included
    int piece;  // the piece it is in (PIECES)
};

// Inside branches a pixel may hold at once: only those refracted back in through a pocket
// wait (each inside chain is followed at once, each outside chain too), so a few suffice; a
// full list drops the branch, as the CPU's (64 deep) does, counting it truncated.
const int kMaxWaiting = 8;

// Everything that leaves the stone from the ray refracted in at `entry` through `entry_facet`
// with weight `weight`, every branch traced at index `ior`: as tracer.cpp follows its branches
// (the same depth and weight rules), an inside chain of internal reflections at a time, each
// exit ray followed outside until it leaves for good, its re-entries waiting.
vec3 follow_branches(vec3 entry, vec3 inward, float weight, int entry_facet, float ior) {
    vec3 colour = vec3(0.0);
    Inside waiting[kMaxWaiting];
    waiting[0] = Inside(entry, inward, weight, 0.0, entry_facet, 1, entry_piece(entry, inward));
    int top = 1;
    while (top > 0) {
        Inside b = waiting[--top];
        vec3 o = b.origin;
        vec3 d = b.direction;
        float w = b.weight;
        int from = b.facet;
        int piece = b.piece;
        for (int depth = b.depth; depth <= u_max_depth && w >= u_min_weight; ++depth) {
            float t;
            int facet;
            if (!next_exit(o, d, from, piece, t, facet)) break;
            vec3 p = o + t * d;
            vec3 n = facet_plane(facet).xyz;
            b.path_mm += t;
            vec3 out_dir;
            vec2 split = leave_stone(d, n, ior, out_dir);
            // The exit ray (its depth the segment's): through a pocket's wall it may meet the
            // stone again, each entry splitting it into a reflection, followed on outside,
            // and a refraction back in, which waits; the entries' branches count a segment.
            vec3 q = p;
            vec3 e = out_dir;
            vec3 m = n;
            float we = w * split.y;
            int on = facet;
            int e_depth = depth;
            while (split.y > 0.0 && we >= u_min_weight) {
                float te;
                int entered;
                int into;
                if (!may_reenter(on) || !next_entry_from(q, e, on, te, entered, into)) {
                    colour += shade_exit(q, e, m, on, we, b.path_mm, environment(q, e));
                    break;
                }
                if (++e_depth > u_max_depth) break;
                q += te * e;
                m = facet_plane(entered).xyz;
                vec2 s = split_weight(-dot(e, m), kAir, ior);
                vec3 in_dir;
                if (top < kMaxWaiting && s.y > 0.0 && we * s.y >= u_min_weight &&
                    refract_ray(e, m, kAir, ior, in_dir)) {
                    waiting[top++] = Inside(q, in_dir, we * s.y, b.path_mm, entered, e_depth, into);
                }
                e = reflect(e, m);
                we *= s.x;
                on = entered;
            }
            o = p;
            d = reflect(d, n);
            w *= split.x;
            from = facet;
        }
    }
    return colour;
}

#endif

// The colour of the pixel's ray (origin, direction) entering the stone through `facet`.
vec3 shade_entry(int facet, vec3 origin, vec3 direction) {
    // The pixel's own ray meets the facet the rasteriser found where its plane is: the entry
    // point as exact as a plane test makes it (the interpolated v_position is a rounding
    // further off, enough to tip a deep path over an edge).
    vec4 entry_plane = facet_plane(facet);
    vec3 n = entry_plane.xyz;
    float facing = dot(n, direction);
#ifdef VISIBILITY
    // Where the pixel's ray crosses the plane of the facet the visibility pass found nearest
    // (facing it, but for a rounding at a grazing view, which crosses the plane all the same).
    float crossing = abs(facing) > 1e-12 ? facing : -1e-12;
    vec3 entry = origin + ((entry_plane.w - dot(n, origin)) / crossing) * direction;
#else
    vec3 entry = facing < 0.0 ? origin + ((entry_plane.w - dot(n, origin)) / facing) * direction
                              : v_position;
#endif
#ifdef SEES_PIECE
    start_sight();
#endif
#ifdef FIRE_EXACT
    // Each channel's trace reflected and refracted at its own index, its colour mixed into the
    // channels; the reflection shaded once.
    vec3 reflected;
    vec3 colour = vec3(0.0);
    for (int k = 0; k < 3; ++k) {
        float ior = u_ior_channel[k];
        vec2 s = split_weight(-dot(direction, n), kAir, ior);
        reflected[k] = s.x;
        vec3 d;
#ifdef SEES_PIECE
        // One channel's exits are followed into the piece, for all three: one trace's exit
        // weighed by its own channel's column made the correction a wavelength's colour, a
        // rainbow grain on small stones after 16 frames (stone_sight.glsl).
        g_channel_mix = k == 1 ? u_channel_mix * vec3(1.0) : vec3(0.0);
#endif
        if (refract_ray(direction, n, kAir, ior, d) && s.y > 0.0) {
#ifdef NON_CONVEX
            colour += u_channel_mix[k] * follow_branches(entry, d, s.y, facet, ior);
#else
            colour += u_channel_mix[k] * follow_inside(entry, d, vec3(0.0), facet, s.y, ior);
#endif
        }
    }
#ifdef SEES_PIECE
    g_channel_mix = u_channel_mix * reflected;
#endif
    colour +=
        (u_channel_mix * reflected) * shade_reflected(entry, reflect(direction, n), n, facet, 1.0);
#else
    vec2 split = split_weight(-dot(direction, n), kAir, u_ior);
    vec3 colour = shade_reflected(entry, reflect(direction, n), n, facet, split.x);
    vec3 inward;
    bool refracted = refract_ray(direction, n, kAir, u_ior, inward);
#ifdef NON_CONVEX
    if (refracted && split.y > 0.0) colour += follow_branches(entry, inward, split.y, facet, u_ior);
#else
    // A convex stone holds one branch: the internal reflection; exit rays cannot come back.
    if (refracted && split.y > 0.0) {
        // d(inward)/dn at the entry: eta = 1/n, d eta/dn = -eta^2.
        float eta = kAir / u_ior;
        vec3 dd = kFirstOrder
                      ? refraction_derivative(direction, vec3(0.0), n, eta, -eta * eta)
                      : vec3(0.0);
        colour += follow_inside(entry, inward, dd, facet, split.y, u_ior);
    }
#endif
#endif
#ifdef SEES_PIECE
    colour += stone_correction();
#endif

    return colour;
}

void main() {
    vec3 origin;
    vec3 direction;
    camera_ray(fragment_ndc(gl_FragCoord), origin, direction);
#if defined(VISIBILITY_SAMPLES)
    // The facets the stone shows at this pixel's samples, each with its count. A block's
    // pixels with none of the stone's samples still run (their values feed its derivatives)
    // and write nothing the stencil keeps. Facets are held to this stone's, as below.
    ivec2 texel = ivec2(gl_FragCoord.xy);
    int facets[kMaxSamples];
    int counts[kMaxSamples];
    int distinct = 0;
    for (int s = 0; s < u_samples; ++s) {
        uvec2 seen = texelFetch(u_visibility, texel, s).rg;
        if (seen.g != u_stone) continue;
        int facet = min(int(seen.r), u_facet_count - 1);
        int k = 0;
        while (k < distinct && facets[k] != facet) ++k;
        if (k == distinct) {
            facets[k] = facet;
            counts[k] = 0;
            ++distinct;
        }
        ++counts[k];
    }
    vec3 colour = vec3(0.0);
    int held = 0;
    for (int k = 0; k < distinct; ++k) {
        colour += float(counts[k]) * shade_entry(facets[k], origin, direction);
        held += counts[k];
    }
    o_colour = vec4(held > 0 ? colour / float(held) : vec3(0.0), 1.0);
#elif defined(VISIBILITY)
    // The stencil test kept this stone's pixels only; a block's other pixels still run (their
    // values feed its derivatives) and may read another stone's facet or none: held to this
    // stone's facets, so that no index runs past its arrays.
    int facet =
        min(int(texelFetch(u_visibility, ivec2(gl_FragCoord.xy), 0).r), u_facet_count - 1);
    o_colour = vec4(shade_entry(facet, origin, direction), 1.0);
#else
    o_colour = vec4(shade_entry(int(v_facet), origin, direction), 1.0);
#endif
}
