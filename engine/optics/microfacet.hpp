#pragma once
// The metal's reflection, one model for the CPU reference and the GPU: a microfacet BRDF with
// the GGX distribution and separable Smith masking (Walter et al., "Microfacet Models for
// Refraction through Rough Surfaces", EGSR 2007, eq. 33-34), alpha = roughness² (Burley,
// "Physically-Based Shading at Disney", 2012), and Schlick's Fresnel from the metal's F0.
//   f(v, l) = F(v·h) D(n·h) G1(n·v) G1(n·l) / (4 (n·v)(n·l))
// The GPU splits its environment lighting into the environment filtered by the lobe and the
// "environment BRDF" (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013): for a given
// n·v and roughness, the reflectance of a uniform white environment is F0·scale + bias. Both
// are integrated here numerically, once, into the table the GPU looks them up in.

#include <vector>

#include <glm/glm.hpp>

namespace gem {

inline constexpr double kMinimumAlpha = 1e-4;

// alpha of GGX for a perceptual roughness 0..1.
inline double ggx_alpha(double roughness) {
    return roughness * roughness > kMinimumAlpha ? roughness * roughness : kMinimumAlpha;
}

// GGX's distribution of microfacet normals, per steradian of m (Walter eq. 33).
double ggx_distribution(double n_dot_m, double alpha);
// Smith's masking of direction x for GGX (Walter eq. 34).
double smith_g1(double n_dot_x, double alpha);
// Schlick's approximation of a conductor's Fresnel reflectance from its F0.
glm::dvec3 schlick_fresnel(const glm::dvec3& f0, double cos_theta);

// A microfacet normal drawn from D(m)(n·m) about n (Walter eq. 35-36) for uniform u1, u2.
glm::dvec3 sample_ggx_normal(const glm::dvec3& n, double alpha, double u1, double u2);

// The direction l = reflect(-v, m) for a normal m drawn through sample_ggx_normal, and its
// weight F G |v·m| / (|n·v| |n·m|) (Walter eq. 38); the weight is zero where l falls below the
// surface.
struct GgxReflection {
    glm::dvec3 direction{0.0};
    glm::dvec3 weight{0.0};
};
GgxReflection ggx_reflect(const glm::dvec3& f0, const glm::dvec3& n, const glm::dvec3& v,
                          const glm::dvec3& m, double alpha);

// The environment BRDF: reflectance of a uniform white environment is f0·scale + bias.
struct EnvironmentBrdf {
    double scale = 0.0;
    double bias = 0.0;
};
// Integrated over `samples` visible normals on a Hammersley set (deterministic); against
// quadrature (optics_microfacet_test.cpp) 1024 are within 1e-3, 256 within 3e-3.
EnvironmentBrdf environment_brdf(double n_dot_v, double roughness, int samples = 1024);

// The table the GPU reads: size × size texel centres, n·v = (i + 0.5)/size along a row,
// roughness = (j + 0.5)/size down the columns; two floats (scale, bias) a texel.
std::vector<float> environment_brdf_table(int size, int samples = 256);

}  // namespace gem
