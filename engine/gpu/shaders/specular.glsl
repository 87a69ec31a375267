// The lights every shading program shares (shading.glsl, phong.frag, metal.glsl): how many
// there are at most, how many are compiled in (LIGHT_COUNT, program_variants.hpp), where each
// lies, and c^h, their specular lobes' falloff. A whole exponent is
// compiled in (SPECULAR_POWER, program_variants.hpp) and taken by repeated squaring, about
// 2 log2(h) multiplications where pow costs a log2 and an exp2 polynomial: on llvmpipe,
// trace's stone pass took 0.94 times and phong's 0.97 times as long at h = 60 (bench_gpu,
// zoom 0.5, medians of ten alternated runs).
#define MAX_LIGHTS 4  // scene/lights.hpp: kMaxLights
#ifndef LIGHT_COUNT
#define LIGHT_COUNT 0
#endif

uniform float u_h;

// The unit direction from p toward a light at `position` (w = 1: a point; w = 0: the
// direction to it, the same from everywhere).
vec3 toward_light(vec4 position, vec3 p) {
    return normalize(position.w > 0.5 ? position.xyz - p : position.xyz);
}

float specular_power(float c) {
#ifdef SPECULAR_POWER
    // The loop and its tests fold away: SPECULAR_POWER is a constant, the count too.
    float result = 1.0;
    float square = c;
    for (int bit = 0; bit < 10; ++bit) {  // program_variants.hpp: kMaxSpecularPower, 10 bits
        if (((SPECULAR_POWER >> bit) & 1) != 0) result *= square;
        square *= square;
    }
    return result;
#else
    return pow(c, u_h);
#endif
}
