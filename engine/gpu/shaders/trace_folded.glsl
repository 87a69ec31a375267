// The trace method's exit by folding (trace.frag, EXIT_FOLDED): a convex mirror-symmetric
// stone's ray folded into one wedge, the few planes there tested as constants.
#if !defined(NON_CONVEX) && defined(EXIT_FOLDED)
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
