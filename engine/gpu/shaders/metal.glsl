// The metal's shading (ring_renderer.hpp), the CPU reference's model (optics/microfacet.hpp):
// GGX distribution and separable Smith masking (Walter et al. 2007), alpha = roughness², and
// Schlick's Fresnel from F0. The environment is image-based light by the split sum
// (metal_environment.hpp): the environment filtered by the lobe, read along the reflected
// direction, times the environment BRDF looked up by n·v and roughness.
// A light is what the CPU reference makes of it: a lobe of radiance colour·(ω·l)^h about its
// direction (scene/lights.hpp). Its reflection is the BRDF integrated over that lobe,
// approximated as the lobe's solid angle 2π/(h+1) times a GGX widened by it: near their peaks
// both are Gaussians in the half-vector's angle, of variances alpha²/4 and 1/(4h), so the
// widened alpha² is alpha² + 1/h. Follows specular.glsl (the lights).
// Everything is in the piece's frame, linear RGB. The uniforms carry the metal's and the
// piece's names: a stone's program that follows its exits onto the metal (stone_sight.glsl)
// holds them beside its own, whose lights are in the stone's frame.

const float kPi = 3.14159265358979;

uniform samplerCube u_metal_environment;  // filtered for this metal's roughness
uniform sampler2D u_environment_brdf;     // (scale, bias) by (n·v, roughness)
uniform vec3 u_metal_f0;
uniform float u_metal_roughness;
uniform float u_metal_alpha;       // GGX alpha of the roughness (optics/microfacet.hpp)
uniform float u_metal_alpha_lit;   // ... widened by the lights' lobe
uniform float u_lobe_solid_angle;  // of a light's lobe, 2π/(h+1)
// w = 1: point light (mm); w = 0: direction to it; in the piece's frame
uniform vec4 u_piece_light_position[MAX_LIGHTS];
uniform vec3 u_piece_light_colour[MAX_LIGHTS];

vec3 fresnel_schlick(vec3 f0, float cos_theta) {
    return f0 + (1.0 - f0) * pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);
}

float ggx(float n_h, float a) {
    float a2 = a * a;
    float d = n_h * n_h * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

float smith_g1(float n_x, float a) {
    float a2 = a * a;
    return 2.0 * n_x / (n_x + sqrt(a2 + (1.0 - a2) * n_x * n_x));
}

// The metal at p, its shading normal n, seen from direction v: the lights and the environment.
vec3 metal_radiance(vec3 p, vec3 n, vec3 v) {
    // Interpolated normals may face slightly away from the eye at silhouettes.
    float n_v = max(dot(n, v), 1e-4);
    vec3 colour = vec3(0.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec3 l = toward_light(u_piece_light_position[i], p);
        float n_l = dot(n, l);
        if (n_l <= 0.0) continue;
        vec3 h = normalize(l + v);
        float n_h = max(dot(n, h), 0.0);
        vec3 f = fresnel_schlick(u_metal_f0, dot(v, h));
        float g = smith_g1(n_v, u_metal_alpha) * smith_g1(n_l, u_metal_alpha);
        vec3 brdf = f * (ggx(n_h, u_metal_alpha_lit) * g / (4.0 * n_l * n_v));
        colour += u_piece_light_colour[i] * u_lobe_solid_angle * brdf * n_l;
    }
    vec3 r = reflect(-v, n);
    vec2 scale_bias = texture(u_environment_brdf, vec2(n_v, u_metal_roughness)).rg;
    colour += textureLod(u_metal_environment, r, 0.0).rgb *
              (u_metal_f0 * scale_bias.x + scale_bias.y);
    return colour;
}
