// Rays followed through a whole piece in a still view's frames: its metal's and stones'
// triangles in one bounding volume hierarchy (piece/sight_mesh.hpp, piece_sight.hpp), walked
// from the metal's reflections (metal_sight.glsl) and from the stones' exits (stone_sight.glsl)
// as the exact reference follows them (cpu/piece_tracer.cpp). Compiled in with SEES_PIECE;
// follows texel.glsl, specular.glsl (the lights' lobes) and metal.glsl (the metal's shading).
// Everything here is in the piece's frame.

#ifdef SEES_PIECE
uniform highp sampler2D u_bvh_nodes;      // piece/sight_mesh.hpp's layout
uniform highp sampler2D u_bvh_triangles;
uniform samplerCube u_environment_sharp;  // the environment itself, unfiltered
uniform int u_sample;                     // the still frame's number less one (0, 1, ...)
uniform float u_ray_offset_mm;            // a reflected ray starts this far off the surface
uniform float u_piece_k_s;                // the lights' share in a stone's reflection
uniform float u_piece_k_st;               // ... and in what leaves a stone

const int kBvhStack = 32;         // two nodes a level of sight_mesh.hpp's kSightMeshDepth
const int kPathSurfaces = 3;      // the surfaces a reflected ray's path meets outside stones
const int kInsideSegments = 8;    // ... and its segments inside one, as the trace's depth 8
// A tile of kSightTile² pixels traces one frame in kSightFrames, in turn with its neighbours
// (sight_traced()), its correction weighed kSightFrames times: the mean of the frames is the
// same, and a frame costs a quarter. One ray a pixel and frame made a halo's still frame at
// 1920×1080 on llvmpipe 2.6 s; a tile, not a pixel, because a SIMD rasteriser shades blocks of
// pixels together (llvmpipe 4×4) and a block with one ray costs as much as one with sixteen.
const int kSightTile = 4;
const int kSightFrames = 4;

// Where the ray o + t d, 0 <= t <= t_max, enters node's box (its near side), or -1 where it
// misses it; its first and count in first_count.
float enter_box(int node, vec3 o, vec3 inv, float t_max, out ivec2 first_count) {
    vec4 lo = texelFetch(u_bvh_nodes, texel_of(2 * node), 0);
    vec4 hi = texelFetch(u_bvh_nodes, texel_of(2 * node + 1), 0);
    first_count = ivec2(lo.w, hi.w);
    vec3 t0 = (lo.xyz - o) * inv;
    vec3 t1 = (hi.xyz - o) * inv;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    float enter = max(max(near.x, near.y), max(near.z, 0.0));
    float leave = min(min(far.x, far.y), min(far.z, t_max));
    return enter <= leave ? enter : -1.0;
}

// What a ray from o along d meets first before t_max: the triangle's index and (t, u, v), or
// -1. From outside (`inside` false) only triangles facing the ray count, as the reference's
// next_entry; from inside a stone only a stone's triangles facing away, where it leaves. The
// nearer child first, so that a hit found early prunes the farther one.
int nearest_triangle(vec3 o, vec3 d, bool inside, float t_max, out vec3 tuv) {
    vec3 inv = 1.0 / mix(d, vec3(1e-20), lessThan(abs(d), vec3(1e-20)));
    float facing = inside ? -1.0 : 1.0;
    tuv = vec3(t_max, 0.0, 0.0);
    int best = -1;
    // Each node on the stack with its first and count, read when its box was tested, and
    // where the ray enters that box.
    int stack[kBvhStack];
    ivec2 stack_first_count[kBvhStack];
    float stack_enter[kBvhStack];
    ivec2 root;
    float root_enter = enter_box(0, o, inv, t_max, root);
    if (root_enter < 0.0) return -1;
    stack[0] = 0;
    stack_first_count[0] = root;
    stack_enter[0] = root_enter;
    int top = 1;
    while (top > 0) {
        --top;
        if (stack_enter[top] > tuv.x) continue;  // a nearer hit was found since it was pushed
        int node = stack[top];
        ivec2 own = stack_first_count[top];
        if (own.y == 0) {
            ivec2 left_fc;
            ivec2 right_fc;
            float left = enter_box(node + 1, o, inv, tuv.x, left_fc);
            float right = enter_box(own.x, o, inv, tuv.x, right_fc);
            if (top + 2 > kBvhStack) continue;
            bool left_first = right < 0.0 || (left >= 0.0 && left <= right);
            float far_enter = left_first ? right : left;
            if (far_enter >= 0.0) {
                stack[top] = left_first ? own.x : node + 1;
                stack_first_count[top] = left_first ? right_fc : left_fc;
                stack_enter[top++] = far_enter;
            }
            float near_enter = left_first ? left : right;
            if (near_enter >= 0.0) {
                stack[top] = left_first ? node + 1 : own.x;
                stack_first_count[top] = left_first ? left_fc : right_fc;
                stack_enter[top++] = near_enter;
            }
            continue;
        }
        for (int i = own.x; i < own.x + own.y; ++i) {
            // Möller and Trumbore (1997). det = -d·((b - a) × (c - a)): positive where the
            // triangle faces the ray.
            vec4 a = texelFetch(u_bvh_triangles, texel_of(6 * i), 0);
            vec3 e1 = texelFetch(u_bvh_triangles, texel_of(6 * i + 1), 0).xyz;
            vec3 e2 = texelFetch(u_bvh_triangles, texel_of(6 * i + 2), 0).xyz;
            vec3 p = cross(d, e2);
            float det = dot(e1, p) * facing;
            if (det <= 0.0 || (inside && a.w == 0.0)) continue;
            vec3 s = (o - a.xyz) * facing;
            float u = dot(s, p) / det;
            if (u < 0.0 || u > 1.0) continue;
            vec3 q = cross(s, e1);
            float w = dot(d, q) / det;
            if (w < 0.0 || u + w > 1.0) continue;
            float t = dot(e2, q) / det;
            if (t > 0.0 && t < tuv.x) {
                tuv = vec3(t, u, w);
                best = i;
            }
        }
    }
    return best;
}

// What a ray along d that leaves the piece sees: the environment, and the lights' lobes times
// k (the reference's escaped(): 1 for the metal's reflection, k_s for a stone's, k_st for an
// exit from one, whose light must lie outside the face it left by, `from_normal`).
vec3 escaped(vec3 p, vec3 d, float k, vec3 from_normal) {
    vec3 sum = textureLod(u_environment_sharp, d, 0.0).rgb;
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 l = toward_light(u_piece_light_position[i], p);
        float c = dot(d, l);
        if (c > 0.0 && dot(from_normal, l) >= 0.0) {
            sum += u_piece_light_colour[i] * (k * specular_power(c));
        }
    }
    return sum;
}

// Uniform numbers for this pixel and still frame. The GGX sample's two: a pixel's own offset
// (a hash of its coordinates, Wellons' lowbias32) moved along the R2 sequence (Roberts 2018)
// frame by frame, so a pixel's frames are spread evenly and neighbours differ. The choices
// along its path: the hash run on.
uint mix_bits(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
uint g_random;
// Seeds the choices of this pixel's ray in this round of its tile; the pixel's own hash.
uint seed_random() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint h = mix_bits(pixel.x * 0x9e3779b9u ^ mix_bits(pixel.y));
    g_random = mix_bits(h ^ uint(u_sample / kSightFrames) * 0x85ebca6bu);
    return h;
}
vec2 frame_random() {
    uint h = seed_random();
    vec2 offset = vec2(float(h & 0xffffu), float(h >> 16)) / 65536.0;
    int round_of_tiles = u_sample / kSightFrames;  // this pixel's how-manieth ray
    return fract(offset +
                 float(round_of_tiles) * vec2(0.7548776662466927, 0.5698402909980532));
}
float next_random() {
    g_random = mix_bits(g_random + 0x9e3779b9u);
    return float(g_random >> 8) / 16777216.0;
}

// A reflected direction l drawn from GGX about the shading normal n as seen from v, for
// uniform u (sample_ggx_normal and ggx_reflect, optics/microfacet.cpp), and its weight
// F G |v·m| / (|n·v| |n·m|) (Walter eq. 38); false where l falls below the surface.
bool sample_reflection(vec3 n, vec3 v, vec2 u, out vec3 l, out vec3 weight) {
    float tan2 = u_metal_alpha * u_metal_alpha * u.x / max(1.0 - u.x, 1e-6);
    float cos_t = inversesqrt(1.0 + tan2);
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    vec3 tx = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0))
                                       : cross(n, vec3(0.0, 1.0, 0.0)));
    vec3 ty = cross(n, tx);
    float phi = 2.0 * kPi * u.y;
    vec3 m = sin_t * cos(phi) * tx + sin_t * sin(phi) * ty + cos_t * n;
    float v_m = dot(v, m);
    l = 2.0 * v_m * m - v;
    float n_l = dot(n, l);
    float n_v = dot(n, v);
    float n_m = dot(n, m);
    weight = vec3(0.0);
    if (v_m <= 0.0 || n_l <= 0.0 || n_v <= 0.0 || n_m <= 0.0) return false;
    weight = fresnel_schlick(u_metal_f0, v_m) * (smith_g1(n_v, u_metal_alpha) *
                                                 smith_g1(n_l, u_metal_alpha) * v_m / (n_v * n_m));
    return true;
}

// Unpolarised dielectric reflectance at incidence cosine c from index n1 into n2 (Born and
// Wolf §1.5.2, optics/fresnel.hpp); 1 beyond the critical angle.
float dielectric_fresnel(float c, float n1, float n2) {
    float eta = n1 / n2;
    float sin2_t = eta * eta * max(0.0, 1.0 - c * c);
    if (sin2_t >= 1.0) return 1.0;
    float cos_t = sqrt(1.0 - sin2_t);
    float rs = (n1 * c - n2 * cos_t) / (n1 * c + n2 * cos_t);
    float rp = (n1 * cos_t - n2 * c) / (n1 * cos_t + n2 * c);
    return 0.5 * (rs * rs + rp * rp);
}

// What a ray that leaves the metal or a stone at o along d sees of the piece, one path: a
// stone it meets is entered or reflected off, and within it each face reflects or lets out,
// chosen by its Fresnel reflectance (so the path keeps its weight), dimmed by the body's
// absorption, as the reference's trace weighs its branches; the metal it meets reflects it
// again, drawn from GGX; the environment where it leaves the piece. As the reference's four passes from the eye, the
// path meets at most three surfaces after the pixel's, the last of them, if metal, shaded by
// the split sum; inside a stone it follows at most the trace's eight segments.
// One walk of the hierarchy a step, from outside or from inside a stone, at one place in the
// code: a SIMD rasteriser runs every lane through the longest path, and the walk inlined once
// keeps the program small.
// `k` and `from_normal`: the lights' share where the ray leaves at once, and the face it left
// by (escaped()); `met`: whether the ray meets the piece at all.
vec3 path_radiance(vec3 o, vec3 d, float k, vec3 from_normal, out bool met) {
    vec3 throughput = vec3(1.0);
    int surfaces = 0;      // met outside stones
    int segments = -1;     // inside a stone: its segments so far; -1 outside
    float ior = 1.0;       // the stone's, while inside
    float size = 1e30;     // ... how far a walk inside it reaches
    vec3 absorption = vec3(0.0);
    met = false;
    for (int walk = 0; walk < kPathSurfaces + kInsideSegments; ++walk) {
        bool inside = segments >= 0;
        vec3 tuv;
        int tri = nearest_triangle(o, d, inside, inside ? size : 1e30, tuv);
        if (inside) {
            if (tri < 0) return vec3(0.0);  // lost inside (rounding at an edge): dark
            vec3 q = o + tuv.x * d;
            throughput *= exp(-absorption * tuv.x);
            vec3 m = texelFetch(u_bvh_triangles, texel_of(6 * tri + 3), 0).xyz;
            if (next_random() < dielectric_fresnel(dot(d, m), ior, 1.0)) {
                d = reflect(d, m);
                o = q - m * u_ray_offset_mm;
                // Past the trace's depth: cut, as the trace cuts it.
                if (++segments == kInsideSegments) return vec3(0.0);
            } else {
                d = refract(d, -m, ior);
                o = q + m * u_ray_offset_mm;
                from_normal = m;
                k = u_piece_k_st;
                segments = -1;
            }
            continue;
        }
        if (walk == 0) met = tri >= 0;
        if (tri < 0 || surfaces == kPathSurfaces) break;
        ++surfaces;
        vec4 a = texelFetch(u_bvh_triangles, texel_of(6 * tri), 0);
        vec3 p = o + tuv.x * d;
        vec4 na = texelFetch(u_bvh_triangles, texel_of(6 * tri + 3), 0);
        if (a.w == 0.0) {
            vec3 nb = texelFetch(u_bvh_triangles, texel_of(6 * tri + 4), 0).xyz;
            vec3 nc = texelFetch(u_bvh_triangles, texel_of(6 * tri + 5), 0).xyz;
            vec3 n = normalize((1.0 - tuv.y - tuv.z) * na.xyz + tuv.y * nb + tuv.z * nc);
            if (dot(n, -d) <= 1e-6) {  // a shading normal facing away: the face's own
                vec3 e1 = texelFetch(u_bvh_triangles, texel_of(6 * tri + 1), 0).xyz;
                vec3 e2 = texelFetch(u_bvh_triangles, texel_of(6 * tri + 2), 0).xyz;
                n = normalize(cross(e1, e2));
            }
            // The last surface, if metal, by the split sum; before it, reflected again.
            if (surfaces == kPathSurfaces) return throughput * metal_radiance(p, n, -d);
            vec3 weight;
            if (!sample_reflection(n, -d, vec2(next_random(), next_random()), d, weight)) {
                return vec3(0.0);
            }
            throughput *= weight;
            o = p + n * u_ray_offset_mm;
            k = 1.0;
            from_normal = vec3(0.0);
            continue;
        }
        // A stone: its index in a.w, its size in b - a's w, its facet's outward normal and its
        // absorption per mm in the normals' texels (piece/sight_mesh.hpp).
        vec3 n = na.xyz;
        ior = a.w;
        if (next_random() < dielectric_fresnel(-dot(d, n), 1.0, ior)) {
            d = reflect(d, n);
            o = p + n * u_ray_offset_mm;
            k = u_piece_k_s;
            from_normal = n;
            continue;
        }
        size = texelFetch(u_bvh_triangles, texel_of(6 * tri + 1), 0).w;
        absorption = vec3(na.w, texelFetch(u_bvh_triangles, texel_of(6 * tri + 4), 0).w,
                          texelFetch(u_bvh_triangles, texel_of(6 * tri + 5), 0).w);
        d = refract(d, n, 1.0 / ior);
        o = p - n * u_ray_offset_mm;
        segments = 0;
    }
    if (segments >= 0) return vec3(0.0);
    return throughput * escaped(o, d, k, from_normal);
}

// Whether this pixel's tile traces in this frame: each tile every kSightFrames-th frame, from a
// frame of its own (a hash of the tile). A still view may stop after any count of frames, when
// some tiles have traced once more than others; tiles taking their turns in a regular order
// (2×2 groups) made that a regular grid on the metal, visible at a glance where the metal sees
// much of its piece; in the hash's order it is a grain.
bool sight_traced() {
    uvec2 tile = uvec2(gl_FragCoord.xy) / uint(kSightTile);
    uint turn = mix_bits(tile.x * 0x9e3779b9u ^ mix_bits(tile.y + 0x632be5abu));
    return (turn + uint(u_sample)) % uint(kSightFrames) == 0u;
}
#endif
