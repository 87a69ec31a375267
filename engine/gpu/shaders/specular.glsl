// c^h, the lights' specular lobes' falloff (shading.glsl, phong.frag). A whole exponent is
// compiled in (SPECULAR_POWER, program_variants.hpp) and taken by repeated squaring, about
// 2 log2(h) multiplications where pow costs a log2 and an exp2 polynomial: on llvmpipe,
// trace's stone pass took 0.94 times and phong's 0.97 times as long at h = 60 (bench_gpu,
// zoom 0.5, medians of ten alternated runs).
uniform float u_h;

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
