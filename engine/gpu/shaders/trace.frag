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
// The parts: trace_common.glsl (inputs, uniforms, the split at a facet), trace_folded.glsl
// (EXIT_FOLDED), trace_pieces.glsl (NON_CONVEX's exits), then this file.

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

// EXIT_FOLDED: exit_by_folding, trace_folded.glsl.

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

// entry_piece, may_reenter, next_exit, stone_ahead: trace_pieces.glsl.

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
