// The thesis' shading stage from ray-tables, per fragment of the stone pass: find the stored
// pixel of up to two stored views (q = M p: roll, zoom and symmetry as an image map), read its ray-list
// (first reflection, then the exit rays), bring every ray into the stone frame (the view
// was folded by a symmetry g: stone = g^T stored) and shade it with shading.glsl. Two views
// are blended by weight (between stored directions, TWO_VIEWS); one view is the nearest-view
// method. FIRE_FIRST_ORDER: dispersion from each ray's d(dir)/dn (program_variants.hpp).
// SEES_PIECE: in a piece's still frames, the exits followed into the piece (stone_sight.glsl).
out vec4 o_colour;

uniform float u_blend;      // weight of view 0; view 1 gets 1 - u_blend
uniform float u_field_mm;   // the stored views' image side, mm through the centre
uniform float u_image_scale;  // image-plane mm per unit of u_cam_half (1, or D for perspective)
uniform vec3 u_dn_channel;  // n(channel) - n(D) for R, G, B: dispersion from d(dir)/dn

// One stored view: pixels (RG32UI: first ray, ray count; row 0 = the image's top row),
// rays a (RGBA32F: direction, weight), rays b (position mm, path mm), rays c (d dir/dn, facet).
uniform highp usampler2D u_pixels0;
uniform highp sampler2D u_rays_a0;
uniform highp sampler2D u_rays_b0;
uniform highp sampler2D u_rays_c0;
uniform mat2 u_image_map0;
uniform mat3 u_to_stone0;
uniform int u_side0;
uniform highp usampler2D u_pixels1;
uniform highp sampler2D u_rays_a1;
uniform highp sampler2D u_rays_b1;
uniform highp sampler2D u_rays_c1;
uniform mat2 u_image_map1;
uniform mat3 u_to_stone1;
uniform int u_side1;

// Shades the ray-list under image point p (mm) of one view; false when the pixel misses.
bool shade_view(vec2 p, usampler2D pixels, sampler2D rays_a, sampler2D rays_b,
                sampler2D rays_c, mat2 image_map, mat3 to_stone, int side,
                out vec3 colour) {
    vec2 q = image_map * p;
    vec2 cell = vec2(q.x / u_field_mm + 0.5, 0.5 - q.y / u_field_mm) * float(side);
    if (any(lessThan(cell, vec2(0.0))) || any(greaterThanEqual(cell, vec2(float(side)))))
        return false;
    uvec2 list = texelFetch(pixels, ivec2(cell), 0).xy;
    if (list.y == 0u) return false;
    int first = int(list.x);
    int count = int(list.y);
    colour = vec3(0.0);
    for (int k = 0; k < count; ++k) {
        ivec2 t = texel_of(first + k);
        vec4 a = texelFetch(rays_a, t, 0);
        vec4 b = texelFetch(rays_b, t, 0);
        vec4 c = texelFetch(rays_c, t, 0);
        vec3 d = to_stone * a.xyz;
        vec3 pos = to_stone * b.xyz;
        int facet = int(c.w + 0.5);
        vec3 n = to_stone * facet_plane(facet).xyz;
        if (k == 0) {
            colour += shade_reflected(pos, d, n, facet, a.w);
            continue;
        }
#ifdef FIRE_FIRST_ORDER
        vec3 dn = to_stone * c.xyz;
        vec3 env = vec3(environment(pos, normalize(d + dn * u_dn_channel.r)).r,
                        environment(pos, normalize(d + dn * u_dn_channel.g)).g,
                        environment(pos, normalize(d + dn * u_dn_channel.b)).b);
#else
        vec3 env = environment(pos, d);
#endif
        colour += shade_exit(pos, d, n, facet, a.w, b.w, env);
    }
    return true;
}

void main() {
    vec2 p = image_plane(fragment_ndc(gl_FragCoord)) * u_image_scale;
    vec3 c0 = vec3(0.0);
    vec3 c1 = vec3(0.0);
#ifdef TWO_VIEWS
    float w0 = u_blend;
#else
    float w0 = 1.0;
#endif
    float w1 = 1.0 - w0;
#ifdef SEES_PIECE
    // In a piece's still frames the stored exits are followed into it as the trace's are
    // (stone_sight.glsl), each view's by its share of the blend.
    start_sight();
    g_channel_mix = vec3(w0);
#endif
    bool hit0 = shade_view(p, u_pixels0, u_rays_a0, u_rays_b0, u_rays_c0, u_image_map0,
                           u_to_stone0, u_side0, c0);
#ifdef TWO_VIEWS
#ifdef SEES_PIECE
    g_channel_mix = vec3(w1);
#endif
    bool hit1 = shade_view(p, u_pixels1, u_rays_a1, u_rays_b1, u_rays_c1, u_image_map1,
                           u_to_stone1, u_side1, c1);
#else
    bool hit1 = false;
#endif
    float coverage = (hit0 ? w0 : 0.0) + (hit1 ? w1 : 0.0);
    if (coverage <= 0.0) discard;
    // Straight colour with alpha = coverage: blending gives w0 c0 + w1 c1 + (1 - a) background.
    // Where the stone is drawn but a stored view saw it miss (its silhouette from another
    // direction), that view's share shows what is behind.
    vec3 sum = (hit0 ? w0 * c0 : vec3(0.0)) + (hit1 ? w1 * c1 : vec3(0.0));
#ifdef SEES_PIECE
    sum += stone_correction();
#endif
    o_colour = vec4(sum / coverage, coverage);
}
