// Fresnel reflectance, refraction and total internal reflection against textbook optics
// (Born & Wolf, Principles of Optics, §1.5): every expected value is an analytic formula
// evaluated here, independently of fresnel.cpp, or a published figure.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "optics/fresnel.hpp"

namespace gem {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDiamond = 2.417;      // GIA Gem Reference Guide, n_D
constexpr double kCrownGlass = 1.5168;  // Schott N-BK7 datasheet, n_d

double degrees(double radians) {
    return radians * 180.0 / kPi;
}
double radians(double degrees) {
    return degrees * kPi / 180.0;
}

// Unit direction arriving at angle `theta` to the normal `n` (against it), in the plane
// spanned by n and the unit tangent t.
glm::dvec3 incident(const glm::dvec3& n, const glm::dvec3& t, double theta) {
    return -std::cos(theta) * n + std::sin(theta) * t;
}

TEST(OpticsFresnel, NormalIncidenceMatchesClosedForm) {
    for (double n : {kDiamond, kCrownGlass, 1.333, 2.65}) {
        const double expected = std::pow((n - 1.0) / (n + 1.0), 2.0);
        EXPECT_NEAR(fresnel_reflectance(1.0, 1.0, n), expected, 1e-12) << "n = " << n;
        // Same from inside: normal incidence does not care about the direction.
        EXPECT_NEAR(fresnel_reflectance(1.0, n, 1.0), expected, 1e-12) << "n = " << n;
    }
    // Published figures: diamond reflects 17.2 % at its table, crown glass about 4.2 %.
    EXPECT_NEAR(fresnel_reflectance(1.0, 1.0, kDiamond), 0.172, 5e-4);
    EXPECT_NEAR(fresnel_reflectance(1.0, 1.0, kCrownGlass), 0.042, 5e-4);
}

TEST(OpticsFresnel, NoPPolarisedReflectionAtBrewstersAngle) {
    const double pairs[][2] = {{1.0, kCrownGlass}, {1.0, kDiamond}, {kDiamond, 1.0}, {1.5, 1.0}};
    for (const auto& [n1, n2] : pairs) {
        const double brewster = std::atan(n2 / n1);
        const FresnelTerms at = fresnel(std::cos(brewster), n1, n2);
        EXPECT_LT(at.rp, 1e-20) << n1 << " -> " << n2;
        EXPECT_GT(at.rs, 0.01) << n1 << " -> " << n2;  // s-light still reflects
        // Either side of Brewster's angle p-light reflects again.
        EXPECT_GT(fresnel(std::cos(brewster - radians(5.0)), n1, n2).rp, 1e-4);
        EXPECT_GT(fresnel(std::cos(brewster + radians(5.0)), n1, n2).rp, 1e-4);
    }
}

TEST(OpticsFresnel, TotalInternalReflectionBeyondCriticalAngle) {
    // Diamond's critical angle: asin(1/2.417) = 24.44° (published as 24.4°).
    EXPECT_NEAR(degrees(critical_angle(kDiamond)), 24.4, 0.05);
    EXPECT_NEAR(critical_angle(kDiamond), std::asin(1.0 / kDiamond), 1e-12);

    const glm::dvec3 n{0.0, 0.0, 1.0};
    const glm::dvec3 t{1.0, 0.0, 0.0};
    const double critical = std::asin(1.0 / kDiamond);
    for (double offset_deg : {0.05, 1.0, 10.0, 40.0, 65.0}) {
        const double beyond = critical + radians(offset_deg);
        EXPECT_EQ(fresnel_reflectance(std::cos(beyond), kDiamond, 1.0), 1.0) << offset_deg;
        EXPECT_FALSE(refract(incident(n, t, beyond), n, kDiamond, 1.0).has_value()) << offset_deg;

        const double below = critical - radians(std::min(offset_deg, 24.0));
        EXPECT_LT(fresnel_reflectance(std::cos(below), kDiamond, 1.0), 1.0) << offset_deg;
        EXPECT_TRUE(refract(incident(n, t, below), n, kDiamond, 1.0).has_value()) << offset_deg;
    }
    // Going into the denser medium there is never total reflection, even at grazing angles.
    EXPECT_LT(fresnel_reflectance(std::cos(radians(89.9)), 1.0, kDiamond), 1.0);
}

// Transmittance from the amplitude transmission coefficients (Born & Wolf eq. 1.5.20) with
// the flux factor (n2 cos θt)/(n1 cos θi) — a different route from 1 − R.
struct Transmittance {
    double s, p;
};
Transmittance transmittance_from_amplitudes(double theta_i, double n1, double n2) {
    const double theta_t = std::asin(n1 * std::sin(theta_i) / n2);
    const double ci = std::cos(theta_i), ct = std::cos(theta_t);
    const double ts = 2.0 * n1 * ci / (n1 * ci + n2 * ct);
    const double tp = 2.0 * n1 * ci / (n2 * ci + n1 * ct);
    const double flux = (n2 * ct) / (n1 * ci);
    return {flux * ts * ts, flux * tp * tp};
}

TEST(OpticsFresnel, ReflectancePlusIndependentTransmittanceIsOne) {
    const double pairs[][2] = {{1.0, kCrownGlass},
                               {1.0, kDiamond},
                               {kDiamond, 1.0},
                               {kCrownGlass, 1.0},
                               {1.333, kDiamond}};
    for (const auto& [n1, n2] : pairs) {
        const double limit = n1 > n2 ? std::asin(n2 / n1) : kPi / 2.0;
        for (int i = 0; i < 50; ++i) {
            const double theta = limit * (i + 0.5) / 50.0;
            const FresnelTerms r = fresnel(std::cos(theta), n1, n2);
            const Transmittance t = transmittance_from_amplitudes(theta, n1, n2);
            EXPECT_NEAR(r.rs + t.s, 1.0, 1e-12) << n1 << " -> " << n2 << " at " << theta;
            EXPECT_NEAR(r.rp + t.p, 1.0, 1e-12) << n1 << " -> " << n2 << " at " << theta;
            EXPECT_NEAR(r.transmittance(), 0.5 * (t.s + t.p), 1e-12);
        }
    }
}

TEST(OpticsFresnel, SameReflectanceFromBothSides) {
    // Stokes reciprocity: light going n1 -> n2 at θi and n2 -> n1 at θt reflect alike.
    for (double n : {kCrownGlass, kDiamond}) {
        for (int i = 0; i < 40; ++i) {
            const double theta_i = (kPi / 2.0) * (i + 0.5) / 40.0;
            const double theta_t = std::asin(std::sin(theta_i) / n);
            const FresnelTerms outside = fresnel(std::cos(theta_i), 1.0, n);
            const FresnelTerms inside = fresnel(std::cos(theta_t), n, 1.0);
            EXPECT_NEAR(outside.rs, inside.rs, 1e-12) << n << " at " << theta_i;
            EXPECT_NEAR(outside.rp, inside.rp, 1e-12) << n << " at " << theta_i;
        }
    }
}

TEST(OpticsFresnel, RefractObeysSnellsLawInThreeDimensions) {
    const double pairs[][2] = {{1.0, kDiamond}, {kDiamond, 1.0}, {1.0, kCrownGlass}, {1.7, 1.2}};
    int checked = 0;
    for (const auto& [n1, n2] : pairs) {
        for (int k = 0; k < 12; ++k) {
            // Normals spread over the sphere, each with a tangent at some angle about it.
            const double polar = kPi * (k + 0.5) / 12.0, azimuth = 2.4 * k;
            const glm::dvec3 n{std::sin(polar) * std::cos(azimuth), std::cos(polar),
                               std::sin(polar) * std::sin(azimuth)};
            const glm::dvec3 helper =
                std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
            const glm::dvec3 t = glm::normalize(glm::cross(n, helper));
            for (int i = 0; i < 30; ++i) {
                const double theta = (kPi / 2.0) * (i + 0.5) / 30.0;
                const glm::dvec3 d = incident(n, t, theta);
                const std::optional<glm::dvec3> out = refract(d, n, n1, n2);
                if (n1 * std::sin(theta) / n2 >= 1.0) {
                    EXPECT_FALSE(out.has_value());
                    continue;
                }
                ASSERT_TRUE(out.has_value()) << n1 << " -> " << n2 << " at " << theta;
                const glm::dvec3 r = *out;
                EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
                EXPECT_LT(glm::dot(r, n), 0.0);  // carries on through the surface
                const double sin_t = glm::length(glm::cross(r, n));
                EXPECT_NEAR(n1 * std::sin(theta), n2 * sin_t, 1e-12);
                // Stays in the plane of incidence, on the far side of the normal from d.
                EXPECT_NEAR(glm::dot(glm::cross(n, t), r), 0.0, 1e-12);
                EXPECT_GE(glm::dot(r, t), 0.0);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 900);
}

TEST(OpticsFresnel, ReflectKeepsAngleAndFlipsNormalComponent) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
    const glm::dvec3 d = glm::normalize(glm::dvec3(-0.3, -1.0, 0.7));
    const glm::dvec3 r = reflect(d, n);
    EXPECT_NEAR(glm::dot(r, n), -glm::dot(d, n), 1e-12);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(glm::cross(d, n), r), 0.0, 1e-12);
}

}  // namespace
}  // namespace gem
