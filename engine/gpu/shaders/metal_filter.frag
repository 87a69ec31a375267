// One face of the metal's environment (metal_environment.hpp): the environment filtered by the
// GGX lobe of the metal's roughness about each texel's direction, taken as the view and the
// normal (the split sum's "prefiltered environment", Karis, "Real Shading in Unreal Engine 4",
// SIGGRAPH 2013, weighted by n·l as there). Each sample reads the source at the mip level whose
// texels cover its share of the lobe's solid angle (Colbert & Krivanek, "GPU-Based Importance
// Sampling", GPU Gems 3, ch. 20), so few samples leave no speckle.

#ifndef SAMPLES
#define SAMPLES 64
#endif
const float kPi = 3.14159265358979;

in vec2 v_ndc;
out vec4 o_colour;

uniform samplerCube u_source;
uniform float u_source_face;  // texels across a face of the source's level 0
uniform float u_alpha;        // GGX alpha = roughness²
uniform vec3 u_forward;       // the face's basis (environment_cube.hpp, cube_face_basis)
uniform vec3 u_right;
uniform vec3 u_up;

// The i-th of SAMPLES points of the Hammersley set.
vec2 hammersley(uint i) {
    uint bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return vec2((float(i) + 0.5) / float(SAMPLES), float(bits) * 2.3283064365386963e-10);
}

void main() {
    vec3 n = normalize(u_forward + v_ndc.x * u_right + v_ndc.y * u_up);
    vec3 tx = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
    vec3 ty = cross(n, tx);
    float a2 = u_alpha * u_alpha;
    float texel_solid_angle = 4.0 * kPi / (6.0 * u_source_face * u_source_face);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int i = 0; i < SAMPLES; ++i) {
        vec2 u = hammersley(uint(i));
        float tan2 = a2 * u.x / max(1.0 - u.x, 1e-6);
        float cos_t = inversesqrt(1.0 + tan2);
        float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
        float phi = 2.0 * kPi * u.y;
        vec3 m = sin_t * cos(phi) * tx + sin_t * sin(phi) * ty + cos_t * n;
        vec3 l = 2.0 * cos_t * m - n;  // the view is the normal: v·m = n·m
        float n_l = dot(n, l);
        if (n_l <= 0.0) continue;
        // The density of l is D(m)(n·m) / (4 v·m) = D(m) / 4 here.
        float d = cos_t * cos_t * (a2 - 1.0) + 1.0;
        float pdf = a2 / (kPi * d * d) / 4.0;
        float level = max(0.5 * log2(1.0 / (float(SAMPLES) * pdf * texel_solid_angle)) + 1.0, 0.0);
        sum += textureLod(u_source, l, level).rgb * n_l;
        weight += n_l;
    }
    o_colour = vec4(sum / max(weight, 1e-6), 1.0);
}
