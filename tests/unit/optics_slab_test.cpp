// Light through an absorbing slab at normal incidence: following every internal reflection
// with fresnel() and beer_lambert() must add up to the closed form of the geometric series,
//   T_total = T² a / (1 − R² a²),   R_total = R + T² R a² / (1 − R² a²),   a = e^(−σL),
// with R = ((n − 1)/(n + 1))² and T = 1 − R (e.g. Born & Wolf §1.6; Hecht, Optics §4.6).

#include <cmath>

#include <gtest/gtest.h>

#include "optics/fresnel.hpp"

namespace gem {
namespace {

struct SlabResult {
    double transmitted = 0.0;
    double reflected = 0.0;
    double absorbed = 0.0;
};

// Follows the light bouncing between the two faces until less than 1e-16 is left.
SlabResult sum_bounces(double n, double sigma_per_mm, double thickness_mm) {
    const FresnelTerms entering = fresnel(1.0, 1.0, n);
    const FresnelTerms leaving = fresnel(1.0, n, 1.0);
    const double pass = beer_lambert(glm::dvec3(sigma_per_mm), thickness_mm).x;

    SlabResult r;
    r.reflected = entering.reflectance();
    double inside = entering.transmittance();  // power heading for the far face
    int passes = 0;
    while (inside > 1e-16) {
        r.absorbed += inside * (1.0 - pass);
        inside *= pass;
        ++passes;
        // Alternate faces: odd passes end at the back face, even ones at the front.
        const double out = inside * leaving.transmittance();
        (passes % 2 == 1 ? r.transmitted : r.reflected) += out;
        inside *= leaving.reflectance();
        EXPECT_LT(passes, 1000);
        if (passes >= 1000) break;
    }
    return r;
}

TEST(OpticsSlab, MultipleReflectionsSumToClosedForm) {
    struct Case {
        double n, sigma, thickness;
    };
    const Case cases[] = {{1.5, 0.3, 2.0},
                          {2.417, 0.3, 2.0},
                          {2.417, 0.0, 5.0},
                          {1.7681, 1.4, 0.7},
                          {2.648, 0.05, 10.0}};
    for (const Case& c : cases) {
        const double R = std::pow((c.n - 1.0) / (c.n + 1.0), 2.0);
        const double T = 1.0 - R;
        const double a = std::exp(-c.sigma * c.thickness);
        const double closed_t = T * T * a / (1.0 - R * R * a * a);
        const double closed_r = R + T * T * R * a * a / (1.0 - R * R * a * a);

        const SlabResult sum = sum_bounces(c.n, c.sigma, c.thickness);
        EXPECT_NEAR(sum.transmitted, closed_t, 1e-12)
            << "n = " << c.n << ", σL = " << c.sigma * c.thickness;
        EXPECT_NEAR(sum.reflected, closed_r, 1e-12) << "n = " << c.n;
        EXPECT_NEAR(sum.transmitted + sum.reflected + sum.absorbed, 1.0, 1e-12);
    }
}

TEST(OpticsSlab, GlassSlabByHand) {
    // n = 1.5: R = 0.04, T = 0.96; σL = 0.6: e^−0.6 = 0.5488116361.
    // T_total = 0.9216 · 0.5488116361 / (1 − 0.0016 · 0.3011942119) = 0.5060286645.
    EXPECT_NEAR(sum_bounces(1.5, 0.3, 2.0).transmitted, 0.5060286645, 1e-9);
    // No absorption: T_total = T / (1 + R) = 0.96 / 1.04 = 0.9230769231 (Hecht §4.6).
    EXPECT_NEAR(sum_bounces(1.5, 0.0, 3.0).transmitted, 0.96 / 1.04, 1e-12);
}

}  // namespace
}  // namespace gem
