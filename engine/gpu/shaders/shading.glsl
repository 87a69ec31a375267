// Shading shared by the table and trace methods (docs/design.md, "Stage 2: shading": thesis
// eq. 6.2-6.5), the GPU twin of engine/scene/shading.cpp: everything here works in the stone
// frame (mm). Follows stone.glsl (the facet planes) and specular.glsl.
//  physical: w_r (E(r) + k_s L(r)) + sum_n w_n exp(-sigma path_n) (E(t_n) + k_st L(t_n))
//  thesis:   w_r k_s L(r) + sum_n w_n I_o k_st L(t_n) + sum_k w_k (E(k) alpha + I_o (1 - alpha))
// E is the environment through the virtual cube, L the lights' specular lobes with the
// obstruction test. SHADING_THESIS picks the thesis' form, CUBE_AT_INFINITY a cube infinitely
// far, ABSORBING a body that absorbs (sigma > 0; program_variants.hpp: paths are compiled in,
// not picked by uniforms).

uniform samplerCube u_environment;
uniform float u_cube_half_mm;  // the virtual cube's half side about the piece's centre
// The stone's frame in the piece's, where the cube stands (identity for a loose stone).
uniform mat3 u_frame_rotation;
uniform vec3 u_frame_origin;
uniform vec4 u_light_position[MAX_LIGHTS];  // w = 1: point light (mm); w = 0: direction to it
uniform vec3 u_light_colour[MAX_LIGHTS];
uniform float u_k_s;
uniform float u_k_st;
uniform float u_alpha;
uniform vec3 u_stone_colour;  // I_o
uniform vec3 u_absorption;    // Beer-Lambert sigma per channel, 1/mm

#ifdef NON_CONVEX
// Triangles, three texels each (a corner per texel, w = the triangle's facet).
uniform highp sampler2D u_triangles;
uniform int u_triangle_count;
#endif

// Where the ray from p along d (stone frame) meets the virtual cube, as a cube-map lookup
// direction: a loose stone's six images were taken from its centre, so the exit point matters,
// not only d (a piece's cubes are looked up by direction: CUBE_AT_INFINITY). The sharp level
// always: neighbouring pixels' rays diverge inside a stone, and a level chosen from their
// derivatives would blur the sparkle.
vec3 environment(vec3 p_stone, vec3 d_stone) {
    vec3 d = u_frame_rotation * d_stone;
#ifdef CUBE_AT_INFINITY
    return textureLod(u_environment, d, 0.0).rgb;
#else
    vec3 p = u_frame_rotation * p_stone + u_frame_origin;
    vec3 far_side = (sign(d) * u_cube_half_mm - p) / d;  // per-axis distance to the far face
    float t = min(far_side.x, min(far_side.y, far_side.z));
    return textureLod(u_environment, p + max(t, 0.0) * d, 0.0).rgb;
#endif
}

#ifdef NON_CONVEX
// Moller & Trumbore (1997); true when the segment from o along d meets a triangle before limit.
bool hits_triangle(vec3 o, vec3 d, int tri, float limit) {
    vec3 a = texelFetch(u_triangles, texel_of(3 * tri), 0).xyz;
    vec3 b = texelFetch(u_triangles, texel_of(3 * tri + 1), 0).xyz;
    vec3 c = texelFetch(u_triangles, texel_of(3 * tri + 2), 0).xyz;
    vec3 e1 = b - a;
    vec3 e2 = c - a;
    vec3 q = cross(d, e2);
    float det = dot(e1, q);
    if (abs(det) < 1e-12) return false;
    float inv = 1.0 / det;
    vec3 s = o - a;
    float u = dot(s, q) * inv;
    if (u < 0.0 || u > 1.0) return false;
    vec3 r = cross(s, e1);
    float v = dot(d, r) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    float t = dot(e2, r) * inv;
    return t > 0.0 && t < limit;
}

#ifdef PIECES
// trace.frag: whether the stone lies within `limit` along d from p, on `facet`, outside.
bool stone_ahead(vec3 p, vec3 d, int facet, float limit);
#endif

// The thesis' obstruction test on a non-convex stone: the leaving facet must face the light,
// and no other part of the stone may lie between the exit point and the light: by the
// stone's convex pieces where trace.frag has them, else by every triangle.
bool light_blocked(vec3 p, vec3 facet_normal, int facet, vec3 to_light, float distance_to_light) {
    if (dot(facet_normal, to_light) <= 0.0) return true;
#ifdef PIECES
    return stone_ahead(p, to_light, facet, distance_to_light);
#else
    vec3 o = p + facet_normal * 1e-4;
    for (int i = 0; i < u_triangle_count; ++i) {
        if (hits_triangle(o, to_light, i, distance_to_light)) return true;
    }
    return false;
#endif
}
#endif

// Sum over the lights of colour * k * (d.L)^h for the ray leaving p along d through `facet`,
// with outward normal n. LIGHT_COUNT is compiled in and the loop unrolled: on llvmpipe a loop
// bounded by a uniform count cost three times the lights' own arithmetic.
vec3 light_specular(vec3 p, vec3 d, vec3 n, int facet, float k) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec4 lp = u_light_position[i];
        vec3 to_light = lp.xyz - p * lp.w;  // w = 1: from p to the point; w = 0: the direction
        float inverse_length = inversesqrt(dot(to_light, to_light));
        to_light *= inverse_length;
        float c = max(dot(d, to_light), 0.0);
#ifdef NON_CONVEX
        if (c <= 0.0) continue;
        float distance = lp.w > 0.5 ? 1.0 / inverse_length : 1e30;
        if (light_blocked(p, n, facet, to_light, distance)) continue;
        sum += u_light_colour[i] * specular_power(c);
#else
        // The obstruction test on a convex stone: only the leaving facet can block a light,
        // by facing away from it (a select, not a branch).
        float unblocked = dot(n, to_light) > 0.0 ? 1.0 : 0.0;
        sum += u_light_colour[i] * (unblocked * specular_power(c));
#endif
    }
    return k * sum;
}

#ifdef SEES_PIECE
// stone_sight.glsl: an exit (or the first reflection) that may be followed into the piece,
// with what the cube (`env`) and the lights showed it.
void sight_candidate(vec3 p, vec3 d, vec3 n, vec3 weight, float k, vec3 env, vec3 lights);
#endif

// The first reflected ray's share of the pixel.
vec3 shade_reflected(vec3 p, vec3 d, vec3 n, int facet, float weight) {
    vec3 env = environment(p, d);
#ifdef SHADING_THESIS
    return weight * (light_specular(p, d, n, facet, u_k_s) + env * u_alpha +
                     u_stone_colour * (1.0 - u_alpha));
#else
    vec3 lights = light_specular(p, d, n, facet, u_k_s);
#ifdef SEES_PIECE
    sight_candidate(p, d, n, vec3(weight), u_k_s, env, lights);
#endif
    return weight * (env + lights);
#endif
}

// One exit ray's share; `env` is what the ray sees (per channel when dispersed).
vec3 shade_exit(vec3 p, vec3 d, vec3 n, int facet, float weight, float path_mm, vec3 env) {
#ifdef SHADING_THESIS
    return weight * (u_stone_colour * light_specular(p, d, n, facet, u_k_st) + env * u_alpha +
                     u_stone_colour * (1.0 - u_alpha));
#else
#ifdef ABSORBING
    vec3 w = weight * exp(-u_absorption * path_mm);
#else
    vec3 w = vec3(weight);  // exp(0) per exit skipped
#endif
    vec3 lights = light_specular(p, d, n, facet, u_k_st);
#ifdef SEES_PIECE
    sight_candidate(p, d, n, w, u_k_st, env, lights);
#endif
    return w * (env + lights);
#endif
}
