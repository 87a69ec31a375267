// The trace method: the exact tracer (engine/trace/tracer.cpp) per fragment, shaded with
// shading.glsl. The entry facet splits the pixel ray into the first reflection and the ray
// inside; every facet hit inside splits a branch into an internal reflection (followed) and a
// refracted exit ray (shaded at once: a shaded ray needs no storage). Depth counts segments,
// branches below u_min_weight are cut, TIR keeps everything: the same rules as the CPU.
// Convex stones: ray/convex-polyhedron by clipping against the facet planes, one branch at a
// time. NON_CONVEX: the triangles, brute force (a heart has a few hundred), and exit rays that
// may re-enter through the cleft wait on a small fixed stack as on the CPU.
in vec2 v_ndc;
out vec4 o_colour;

uniform int u_facet_count;
uniform float u_ior;
uniform int u_max_depth;
uniform float u_min_weight;
uniform int u_thesis_weights;  // 1: constant R/T factors; 0: exact Fresnel
uniform float u_r_factor;
uniform float u_t_factor;

// Weight shares of an interaction at incidence cosine cos_i from index n1 into n2
// (optics/fresnel.cpp; tracer.cpp split_weight). x: reflected, y: transmitted.
vec2 split_weight(float cos_i, float n1, float n2) {
    cos_i = clamp(cos_i, 0.0, 1.0);
    float sin_t2 = (n1 / n2) * (n1 / n2) * (1.0 - cos_i * cos_i);
    if (sin_t2 >= 1.0) return vec2(1.0, 0.0);
    float cos_t = sqrt(1.0 - sin_t2);
    float s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    float r = 0.5 * (s * s + p * p);
    if (r >= 1.0) return vec2(1.0, 0.0);
    if (u_thesis_weights == 1) return vec2(u_r_factor, u_t_factor);
    return vec2(r, 1.0 - r);
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

const float kAir = 1.0;

#ifndef NON_CONVEX

// The entry point: the last plane the ray crosses going in (convex_intersector.cpp).
bool next_entry(vec3 o, vec3 d, out float t_hit, out int facet) {
    float t_in = -1e30;
    float t_out = 1e30;
    facet = -1;
    t_hit = 0.0;
    for (int i = 0; i < u_facet_count; ++i) {
        vec4 plane = facet_plane(i);
        float facing = dot(plane.xyz, d);
        float inside_by = plane.w - dot(plane.xyz, o);
        if (facing < 0.0) {
            float t = inside_by / facing;
            if (t > t_in) {
                t_in = t;
                facet = i;
            }
        } else if (facing > 0.0) {
            t_out = min(t_out, inside_by / facing);
        } else if (inside_by < 0.0) {
            return false;
        }
    }
    if (facet < 0 || t_in > t_out || t_in < 0.0) return false;
    t_hit = t_in;
    return true;
}

// The exit point: the first plane the ray crosses going out, never the one it starts on.
bool next_exit(vec3 o, vec3 d, int from_facet, out float t_hit, out int facet) {
    t_hit = 1e30;
    facet = -1;
    for (int i = 0; i < u_facet_count; ++i) {
        if (i == from_facet) continue;
        vec4 plane = facet_plane(i);
        float facing = dot(plane.xyz, d);
        if (facing <= 0.0) continue;
        // A start point a rounding error outside a plane leaves through it where it is.
        float t = max((plane.w - dot(plane.xyz, o)) / facing, 0.0);
        if (t < t_hit) {
            t_hit = t;
            facet = i;
        }
    }
    return facet >= 0;
}

#else

// Hits down to this far behind the origin count (mm), so a ray starting on an edge that
// leaves straight through the neighbouring facet is caught there (bvh_intersector.cpp uses
// 1e-9 of the diagonal in double; float needs more).
const float kBehind = 1e-5;
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

bool next_entry_from(vec3 o, vec3 d, int from_facet, out float t_hit, out int facet) {
    return nearest_triangle(o, d, from_facet, -1.0, t_hit, facet);
}

bool next_entry(vec3 o, vec3 d, out float t_hit, out int facet) {
    return next_entry_from(o, d, -1, t_hit, facet);
}

// As bvh_intersector.cpp's next_exit; its fallback for a start point on an edge (leave where
// it stands through the steepest neighbour) is approximated by the planes through the point.
bool next_exit(vec3 o, vec3 d, int from_facet, out float t_hit, out int facet) {
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

// A branch of the ray tree (tracer.cpp's Branch).
struct Branch {
    vec3 origin;
    vec3 direction;
    float weight;
    float path_mm;
    int facet;  // facet the branch starts on
    int depth;  // segments followed so far, this one included
    bool inside;
};

// Branches a pixel may hold at once. The exit branch is popped right after it is pushed, so
// each depth level leaves at most two branches waiting (an inside and an outside reflection):
// 32 holds every tree up to max_depth 15. Deeper, a full stack drops the branch, as the CPU
// (64 deep) does, counting it truncated.
const int kMaxBranches = 32;

#endif

void main() {
    vec3 origin;
    vec3 direction;
    camera_ray(v_ndc, origin, direction);

    float t;
    int facet;
    if (!next_entry(origin, direction, t, facet)) discard;
    vec3 entry = origin + t * direction;
    vec3 n = facet_plane(facet).xyz;
    vec2 split = split_weight(-dot(direction, n), kAir, u_ior);
    vec3 colour = shade_reflected(entry, reflect(direction, n), n, split.x);

    vec3 inward;
    bool refracted = refract_ray(direction, n, kAir, u_ior, inward);

#ifndef NON_CONVEX
    // A convex stone holds one branch: the internal reflection; exit rays cannot come back.
    vec3 o = entry;
    vec3 d = inward;
    float weight = refracted ? split.y : 0.0;
    float path = 0.0;
    int from = facet;
    for (int depth = 1; depth <= u_max_depth; ++depth) {
        if (weight <= 0.0 || weight < u_min_weight) break;
        if (!next_exit(o, d, from, t, facet)) break;  // a closed solid always has one
        vec3 p = o + t * d;
        n = facet_plane(facet).xyz;
        path += t;
        split = split_weight(dot(d, n), u_ior, kAir);
        vec3 out_dir;
        float out_weight = weight * split.y;
        if (split.y > 0.0 && refract_ray(d, -n, u_ior, kAir, out_dir) &&
            out_weight >= u_min_weight) {
            colour += shade_exit(p, out_dir, n, out_weight, path, environment(p, out_dir));
        }
        o = p;
        d = reflect(d, n);
        weight *= split.x;
        from = facet;
    }
#else
    Branch stack[kMaxBranches];
    int top = 0;
    if (refracted && split.y > 0.0) {
        stack[0] = Branch(entry, inward, split.y, 0.0, facet, 1, true);
        top = 1;
    }
    while (top > 0) {
        Branch b = stack[--top];
        if (b.weight < u_min_weight || b.depth > u_max_depth) continue;
        if (!b.inside) {
            // Does the exit ray come back through the cleft?
            if (!next_entry_from(b.origin, b.direction, b.facet, t, facet)) {
                n = facet_plane(b.facet).xyz;
                colour += shade_exit(b.origin, b.direction, n, b.weight, b.path_mm,
                                     environment(b.origin, b.direction));
                continue;
            }
            vec3 p = b.origin + t * b.direction;
            n = facet_plane(facet).xyz;
            split = split_weight(-dot(b.direction, n), kAir, u_ior);
            if (top < kMaxBranches && split.x > 0.0) {
                stack[top++] = Branch(p, reflect(b.direction, n), b.weight * split.x, b.path_mm,
                                      facet, b.depth + 1, false);
            }
            vec3 in_dir;
            if (top < kMaxBranches && split.y > 0.0 &&
                refract_ray(b.direction, n, kAir, u_ior, in_dir)) {
                stack[top++] =
                    Branch(p, in_dir, b.weight * split.y, b.path_mm, facet, b.depth + 1, true);
            }
            continue;
        }
        if (!next_exit(b.origin, b.direction, b.facet, t, facet)) continue;
        vec3 p = b.origin + t * b.direction;
        n = facet_plane(facet).xyz;
        float path = b.path_mm + t;
        split = split_weight(dot(b.direction, n), u_ior, kAir);
        // Reflection first, so the exit branch is resolved next and the stack stays shallow.
        if (top < kMaxBranches && split.x > 0.0) {
            stack[top++] =
                Branch(p, reflect(b.direction, n), b.weight * split.x, path, facet, b.depth + 1,
                       true);
        }
        vec3 out_dir;
        if (top < kMaxBranches && split.y > 0.0 &&
            refract_ray(b.direction, -n, u_ior, kAir, out_dir)) {
            stack[top++] = Branch(p, out_dir, b.weight * split.y, path, facet, b.depth, false);
        }
    }
#endif

    o_colour = vec4(colour, 1.0);
    gl_FragDepth = window_depth(entry);
}
