// The metal's BRDF (optics/microfacet.hpp) against integrals taken here by plain quadrature
// over the hemisphere, independently of the importance sampling both renderers use:
//   - GGX's distribution is normalised, ∫ D (n·m) dω = 1;
//   - the white furnace: a rough metal of F0 = 1 in a uniform white environment reflects at
//     most what came in, all of it as it turns smooth, and the environment BRDF (scale + bias)
//     the GPU looks up is that reflectance;
//   - F0 = 0 leaves the Fresnel's grazing part alone: the bias.
// The Karis mobile fit the GPU used before is printed beside them, for the record.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "optics/microfacet.hpp"

namespace gem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ over microfacet normals m (polar angle t, azimuth p; midpoint rule, dω = sin t dt dp) of
// F(v·m) D G1(v) G1(l) (v·m) / (n·v), the reflectance of a white environment written over m
// (dω_l = 4 (v·m) dω_m; Walter et al. 2007, eq. 14), for a scalar F0.
double quadrature_reflectance(double n_dot_v, double roughness, double f0) {
    const double alpha = ggx_alpha(roughness);
    const glm::dvec3 v(std::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    constexpr int kPolar = 3000, kAzimuth = 256;
    double sum = 0.0;
    for (int i = 0; i < kPolar; ++i) {
        const double t = (i + 0.5) * (0.5 * kPi / kPolar);
        const double ct = std::cos(t), st = std::sin(t);
        const double d = ggx_distribution(ct, alpha);
        for (int j = 0; j < kAzimuth; ++j) {
            const double p = (j + 0.5) * (2.0 * kPi / kAzimuth);
            const glm::dvec3 m(st * std::cos(p), st * std::sin(p), ct);
            const double v_dot_m = glm::dot(v, m);
            if (v_dot_m <= 0.0) continue;
            const glm::dvec3 l = 2.0 * v_dot_m * m - v;
            if (l.z <= 0.0) continue;
            const double f = schlick_fresnel(glm::dvec3(f0), v_dot_m).x;
            const double g = smith_g1(n_dot_v, alpha) * smith_g1(l.z, alpha);
            sum += f * d * g * v_dot_m / n_dot_v * st;
        }
    }
    return sum * (0.5 * kPi / kPolar) * (2.0 * kPi / kAzimuth);
}

// Karis, "Physically Based Shading on Mobile" (2014): the fit the metal's shader used, as F0·a + b.
EnvironmentBrdf karis_mobile_fit(double n_dot_v, double roughness) {
    const double r0 = roughness * -1.0 + 1.0, r1 = roughness * -0.0275 + 0.0425;
    const double r2 = roughness * -0.572 + 1.04, r3 = roughness * 0.022 - 0.04;
    const double a004 = std::min(r0 * r0, std::exp2(-9.28 * n_dot_v)) * r0 + r1;
    return {-1.04 * a004 + r2, 1.04 * a004 + r3};
}

TEST(Microfacet, GgxDistributionIsNormalised) {
    for (const double roughness : {0.1, 0.25, 0.5, 1.0}) {
        const double alpha = ggx_alpha(roughness);
        constexpr int kSteps = 200000;
        double sum = 0.0;
        for (int i = 0; i < kSteps; ++i) {
            const double t = (i + 0.5) * (0.5 * kPi / kSteps);
            sum += ggx_distribution(std::cos(t), alpha) * std::cos(t) * std::sin(t);
        }
        EXPECT_NEAR(sum * 2.0 * kPi * (0.5 * kPi / kSteps), 1.0, 1e-3) << roughness;
    }
}

TEST(Microfacet, WhiteFurnaceAndTheEnvironmentBrdfAgreeWithQuadrature) {
    for (const double roughness : {0.1, 0.25, 0.5, 0.8}) {
        for (const double n_dot_v : {0.2, 0.5, 1.0}) {
            const double white = quadrature_reflectance(n_dot_v, roughness, 1.0);
            const double black = quadrature_reflectance(n_dot_v, roughness, 0.0);
            // Single scattering only loses energy (rays masked by other microfacets): at most
            // all of it, and nearly all of it while smooth.
            EXPECT_LE(white, 1.0 + 2e-4) << roughness << " " << n_dot_v;  // the rule's error
            EXPECT_GT(white, roughness <= 0.1    ? 0.99
                             : roughness <= 0.25 ? 0.94
                                                 : 0.5)
                << roughness << " " << n_dot_v;
            const EnvironmentBrdf e = environment_brdf(n_dot_v, roughness);
            EXPECT_NEAR(e.scale + e.bias, white, 1e-3) << roughness << " " << n_dot_v;
            EXPECT_NEAR(e.bias, black, 1e-3) << roughness << " " << n_dot_v;
            const EnvironmentBrdf fit = karis_mobile_fit(n_dot_v, roughness);
            std::printf(
                "roughness %.2f, n·v %.1f: white %.4f, black %.4f; sampled %.4f, %.4f; "
                "Karis' fit %.4f, %.4f\n",
                roughness, n_dot_v, white, black, e.scale + e.bias, e.bias, fit.scale + fit.bias,
                fit.bias);
        }
    }
}

TEST(Microfacet, TheTableHoldsTheIntegralAtItsTexelCentres) {
    constexpr int kSize = 8;
    const std::vector<float> table = environment_brdf_table(kSize);
    ASSERT_EQ(table.size(), 2u * kSize * kSize);
    for (const int j : {0, 3, 7}) {
        for (const int i : {0, 4, 7}) {
            const double n_dot_v = (i + 0.5) / kSize, roughness = (j + 0.5) / kSize;
            const double white = quadrature_reflectance(n_dot_v, roughness, 1.0);
            const float* texel = &table[2 * (j * kSize + i)];
            EXPECT_NEAR(texel[0] + texel[1], white, 3e-3) << i << " " << j;  // 256 samples
        }
    }
}

// The sampler both renderers share draws microfacet normals with density D (n·m): its weights
// average to the quadrature's reflectance over many draws (a different random sequence from
// the table's Hammersley set).
TEST(Microfacet, TheSampleWeightsAverageToTheReflectance) {
    const glm::dvec3 n(0.0, 0.0, 1.0);
    const double n_dot_v = 0.6, roughness = 0.25;
    const glm::dvec3 v(std::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    const glm::dvec3 f0(1.0, 0.716, 0.337);  // yellow gold
    glm::dvec3 sum(0.0);
    constexpr int kDraws = 200000;
    std::uint64_t state = 12345;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0);
    };
    for (int i = 0; i < kDraws; ++i) {
        const double u1 = next(), u2 = next();
        sum += ggx_reflect(f0, n, v, sample_ggx_normal(n, ggx_alpha(roughness), u1, u2),
                           ggx_alpha(roughness))
                   .weight;
    }
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sum[c] / kDraws, quadrature_reflectance(n_dot_v, roughness, f0[c]), 3e-3) << c;
    }
}

}  // namespace
}  // namespace gem
