// Physically based metal (ring_renderer.hpp): Cook-Torrance with the GGX distribution
// (Walter et al. 2007), Smith-Schlick masking with k = (r + 1)^2 / 8 for analytic lights and
// Schlick's Fresnel from F0 (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013). The
// environment is image-based light: the cube along the reflected direction, blurred over a
// cone that widens with roughness (the cube's box-filtered mip level of that width), weighted
// by Karis' analytic fit of the split-sum environment BRDF ("Physically Based Shading on
// Mobile", 2014). LIGHT_COUNT is compiled in (program_variants.hpp).
// A light's colour is taken as the irradiance it gives a surface facing it (no fall-off), as
// the stone's lights have none either. Everything is in the stone frame, linear RGB.

#define MAX_LIGHTS 4
#ifndef LIGHT_COUNT
#define LIGHT_COUNT 0
#endif
const float kPi = 3.14159265358979;

in vec3 v_position;
in vec3 v_normal;
out vec4 o_colour;

uniform samplerCube u_environment;
uniform vec3 u_eye;             // eye position; a direction toward the eye when at infinity
uniform int u_eye_at_infinity;  // 1: orthographic camera
uniform vec3 u_f0;
uniform float u_roughness;
uniform float u_environment_face;  // texels across a cube face at level 0
uniform vec4 u_light_position[MAX_LIGHTS];  // w = 1: point light (mm); w = 0: direction to it
uniform vec3 u_light_colour[MAX_LIGHTS];

vec3 fresnel_schlick(vec3 f0, float cos_theta) {
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);
}

float ggx(float n_h, float a) {
    float a2 = a * a;
    float d = n_h * n_h * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

float smith_schlick(float n_l, float n_v, float roughness) {
    float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    return n_l / (n_l * (1.0 - k) + k) * n_v / (n_v * (1.0 - k) + k);
}

vec3 environment_brdf(vec3 f0, float roughness, float n_v) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * n_v)) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    return f0 * ab.x + ab.y;
}

// A blurrier lookup for rougher metal, over about the GGX lobe's width each side
// (a = roughness^2 radians): the mip level whose texels span 2a. A level-0 texel spans about
// (pi / 2) / face radians, so that level is log2(4 a face / pi). One trilinear lookup in place
// of nine taps around the lobe, which cost a quarter of a ring frame on llvmpipe.
vec3 environment_blurred(vec3 r, float a) {
    float level = log2(max(4.0 * a * u_environment_face / kPi, 1.0));
    return textureLod(u_environment, r, level).rgb;
}

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // a triangle seen from inside (open or badly wound meshes)
    vec3 v = u_eye_at_infinity == 1 ? normalize(u_eye) : normalize(u_eye - v_position);
    float roughness = clamp(u_roughness, 0.0, 1.0);
    float a = max(roughness * roughness, 2e-3);
    // Interpolated normals may face slightly away from the eye at silhouettes.
    float n_v = max(dot(n, v), 1e-4);

    vec3 colour = vec3(0.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec4 lp = u_light_position[i];
        vec3 l = normalize(lp.w > 0.5 ? lp.xyz - v_position : lp.xyz);
        float n_l = dot(n, l);
        if (n_l <= 0.0) continue;
        vec3 h = normalize(l + v);
        float n_h = max(dot(n, h), 0.0);
        vec3 f = fresnel_schlick(u_f0, dot(v, h));
        vec3 brdf = f * (ggx(n_h, a) * smith_schlick(n_l, n_v, roughness) / (4.0 * n_l * n_v));
        colour += u_light_colour[i] * brdf * n_l;
    }
    vec3 r = reflect(-v, n);
    colour += environment_blurred(r, a) * environment_brdf(u_f0, roughness, n_v);
    o_colour = vec4(colour, 1.0);
}
