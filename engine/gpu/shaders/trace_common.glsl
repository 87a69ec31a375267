// The trace method's shared part (trace.frag): the stone pass's inputs, the trace's uniforms,
// and how a ray splits at a facet (Fresnel or the thesis' R/T factors).
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
